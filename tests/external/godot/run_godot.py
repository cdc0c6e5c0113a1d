#!/usr/bin/env python3
"""Godot 3.2 as a second client of our exports: its editor imports a folder
of them, report_scenes.gd loads each imported scene and reports what Godot
made of it, and this script checks the report against what we exported.

usage: run_godot.py GODOT WORK_DIR EXPORTS_DIR CASE...
  CASE is NAME=EXPECTED_JSON: the exports EXPORTS_DIR/NAME.{glb,gltf,fbx,dae}
  and what our engine computed for them, either by expected_pose (a sketch
  exported with --pose-demo: "vertices" of one part at "time") or by
  expected_clips --at-second-key ("clips": per clip and part, a time and
  vertices).

Per case and format it checks, and prints one line per check:
  - Godot imported the file and the scene loads;
  - its Skeletons hold as many bones as the file's skins (the .gltf export
    of the case is the reference for what we exported), each bone with the
    parent we exported;
  - as many skinned meshes as we exported, each bound to a Skeleton;
  - the animations are named as exported;
  - each probe vertex, found at rest within 0.1% of the model's size, is at
    the time of a key where our linear blend skinning puts it, within 1% of
    the model's size, with the weights the format carries (expected_pose
    gives a vertex set per format, expected_clips one for glb and fbx; the
    glb set stands in for the others: every format is cut to the same
    default of four influences).

Godot 3.2.3 imports FBX through its Assimp module, which gives a bone its
parent only when the parent was added to the Skeleton before it, in the
order of the file's clusters (docs/EXCHANGE.md rule 15); our FBX lists them
parents first (io/FbxClusterOrder.h), so every FBX bone must keep its parent
here like any other format's.

Exit codes: 0 all checks passed, 1 a check failed, 77 Godot cannot run here
(the message says why; ctest reports the test as skipped).
"""

import json
import os
import shutil
import signal
import subprocess
import sys
import time

FORMATS = ["glb", "gltf", "fbx", "dae"]
SKIP = 77
POSE_TOLERANCE = 0.01  # of the model size
REST_TOLERANCE = 0.001  # of the model size: the probe found the same vertex
IMPORT_TIMEOUT = 300  # seconds for the editor's import of the whole folder
SETTLE_SECONDS = 3  # after the last .import file, before ending a hung editor
TEMPLATE = os.path.dirname(os.path.abspath(__file__))


def godot_command(godot, project, *arguments):
    # Xvfb gives Godot's GLES3 renderer a display; the Dummy driver needs no sound card.
    return ["xvfb-run", "-a", godot, "--audio-driver", "Dummy", "--path", project, *arguments]


def hermetic_environment(work):
    """The editor's settings and caches in WORK, not in the user's home."""
    env = dict(os.environ)
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        env[name] = os.path.join(work, "home", name.lower())
        os.makedirs(env[name], exist_ok=True)
    return env


def can_run(godot, work):
    """None if Godot runs a script here, else why not."""
    if shutil.which("xvfb-run") is None:
        return "xvfb-run is not installed (Debian packages xvfb xauth)"
    if shutil.which(godot) is None:
        return godot + " is not installed (Debian package godot3)"
    probe = os.path.join(work, "probe")
    os.makedirs(probe, exist_ok=True)
    with open(os.path.join(probe, "project.godot"), "w") as f:
        f.write("config_version=4\n")
    with open(os.path.join(probe, "quit.gd"), "w") as f:
        f.write("extends SceneTree\nfunc _initialize():\n\tprint(\"godot runs\")\n\tquit()\n")
    try:
        run = subprocess.run(godot_command(godot, probe, "-s", "quit.gd"), capture_output=True,
                             text=True, timeout=60, env=hermetic_environment(work))
    except subprocess.TimeoutExpired:
        return "Godot did not finish a one-line script within 60 s"
    if "godot runs" not in run.stdout:
        return "Godot cannot run a script here: " + (run.stdout + run.stderr).strip()[-300:]
    return None


def scene_files(project):
    return sorted(n for n in os.listdir(project) if n.rsplit(".", 1)[-1] in FORMATS)


def imported(project, name):
    """Has the editor tried to import NAME? It writes the scene, then NAME's
    .import file, then the .md5 beside the scene, also when the import
    failed (measured with Godot 3.2.3); a failure shows in the checks."""
    try:
        with open(os.path.join(project, name + ".import")) as f:
            text = f.read()
    except OSError:
        return False
    for line in text.splitlines():
        if line.startswith("path="):
            target = line.split("=", 1)[1].strip().strip('"').replace("res://", "")
            return os.path.exists(os.path.join(project, os.path.splitext(target)[0] + ".md5"))
    return False


def import_folder(godot, project, log):
    """Runs `--editor --quit` until every scene file is imported (twice at
    most). Measured with Godot 3.2.3: the editor imports the folder, then
    often hangs on exit, so once every file is imported it gets a few
    seconds and is then ended."""
    for attempt in range(2):
        editor = subprocess.Popen(godot_command(godot, project, "--editor", "--quit"),
                                  stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
                                  env=hermetic_environment(os.path.dirname(project)))
        started = time.monotonic()
        done_at = None
        while editor.poll() is None:
            if all(imported(project, n) for n in scene_files(project)):
                done_at = done_at or time.monotonic()
                if time.monotonic() - done_at > SETTLE_SECONDS:
                    break
            if time.monotonic() - started > IMPORT_TIMEOUT:
                break
            time.sleep(0.5)
        if editor.poll() is None:
            os.killpg(editor.pid, signal.SIGTERM)
            try:
                editor.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(editor.pid, signal.SIGKILL)
                editor.wait()
        missing = [n for n in scene_files(project) if not imported(project, n)]
        if not missing:
            return []
    return missing


def exported_reference(gltf_path):
    """What the .gltf export holds: per skin its joints' names and parents,
    the number of skinned meshes, the animation names."""
    with open(gltf_path) as f:
        gltf = json.load(f)
    nodes = gltf.get("nodes", [])
    parent = {}
    for index, node in enumerate(nodes):
        for child in node.get("children", []):
            parent[child] = index
    skins = []
    for skin in gltf.get("skins", []):
        joints = set(skin["joints"])
        skins.append({nodes[j]["name"]: (nodes[parent[j]]["name"] if parent.get(j) in joints else None)
                      for j in skin["joints"]})
    skinned = sum(1 for node in nodes if "mesh" in node and "skin" in node)
    animations = sorted(a.get("name", "") for a in gltf.get("animations", []))
    return {"skins": skins, "skinned_meshes": skinned, "animations": animations}


def bone_key(name):
    # Godot's glTF importer writes "biped_bone3" as "biped_bone_3".
    return name.replace("_", "")


def vertex_set(vertices, extension):
    """The expected vertices of the format, or of glb (see above)."""
    return [(v["rest"], v["posed"]) for v in vertices.get(extension, vertices["glb"])]


def probes_of(expected, extension):
    """(animation, part, time, [(rest, posed)]) per probe: one per clip and
    part, or the one demo clip of a sketch."""
    if "clips" in expected:
        for clip, parts in sorted(expected["clips"].items()):
            for part, entry in sorted(parts.items()):
                yield clip, part, entry["time"], vertex_set(entry["vertices"], extension)
    else:
        yield None, expected["part"], expected["time"], vertex_set(expected["vertices"], extension)


def distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5


class Checks:
    def __init__(self):
        self.failed = 0
        self.passed = 0

    def check(self, ok, what):
        print(("ok    " if ok else "FAIL  ") + what)
        if ok:
            self.passed += 1
        else:
            self.failed += 1


def check_file(checks, file, scene, reference, size):
    if not scene.get("loaded"):
        checks.check(False, f"{file}: Godot imported it and the scene loads")
        return
    checks.check(True, f"{file}: Godot imported it and the scene loads")
    want_sizes = sorted(len(s) for s in reference["skins"])
    got_sizes = sorted(len(s["bones"]) for s in scene["skeletons"])
    checks.check(sum(got_sizes) == sum(want_sizes) and len(got_sizes) <= len(want_sizes),
                 f"{file}: {sum(got_sizes)} bones in Skeletons {got_sizes}, exported "
                 f"{sum(want_sizes)} in skins {want_sizes}")
    parents = {}
    for skin in reference["skins"]:
        parents.update({bone_key(b): (bone_key(p) if p else None) for b, p in skin.items()})
    for skeleton in scene["skeletons"]:
        bones = [bone_key(b) for b in skeleton["bones"]]
        right = all(parents.get(b, "?") == (bones[p] if p >= 0 else None)
                    for b, p in zip(bones, skeleton["parents"]))
        checks.check(right, f"{file}: Skeleton {skeleton['path']}: every bone has its exported parent")
    skinned = [m for m in scene["meshes"] if m["skeleton"] and m["weighted"]]
    checks.check(len(skinned) == reference["skinned_meshes"],
                 f"{file}: {len(skinned)} skinned meshes bound to a Skeleton, exported "
                 f"{reference['skinned_meshes']}")
    names = sorted(a["name"] for a in scene["animations"])
    checks.check(names == reference["animations"],
                 f"{file}: animations {names}, exported {reference['animations']}")
    for probe in scene["probes"]:
        label = f"{file}: {probe['animation']} at {probe['time']:g} s ({probe['part']})"
        if "error" in probe:
            checks.check(False, f"{label}: {probe['error']}")
            continue
        rest_off = max(distance(a, b) for a, b in zip(probe["rest"], probe["expected_rest"]))
        pose_off = max(distance(a, b) for a, b in zip(probe["posed"], probe["expected_posed"]))
        what = (f"{label}: {len(probe['rest'])} vertices at rest within {rest_off / size:.2e} and "
                f"posed within {pose_off / size:.2e} of the size {size:.3g} (limits "
                f"{REST_TOLERANCE:g}, {POSE_TOLERANCE:g})")
        ok = rest_off <= REST_TOLERANCE * size and pose_off <= POSE_TOLERANCE * size
        checks.check(ok, what)


def main(argv):
    if len(argv) < 5 or any("=" not in c for c in argv[4:]):
        print(__doc__)
        return 2
    godot, work, exports = argv[1], argv[2], argv[3]
    cases = dict(c.split("=", 1) for c in argv[4:])
    started = time.monotonic()
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    why = can_run(godot, work)
    if why is not None:
        print("run_godot: skipped: " + why)
        return SKIP

    project = os.path.join(work, "project")
    os.makedirs(project)
    for name in ("project.godot", "report_scenes.gd"):
        shutil.copy(os.path.join(TEMPLATE, name), project)
    expected, references, request = {}, {}, {"scenes": []}
    for case, expected_path in sorted(cases.items()):
        with open(expected_path) as f:
            expected[case] = json.load(f)
        references[case] = exported_reference(os.path.join(exports, case + ".gltf"))
        for extension in FORMATS:
            shutil.copy(os.path.join(exports, f"{case}.{extension}"), project)
        for companion in os.listdir(exports):  # the .gltf's buffer
            if companion.startswith(case + ".") and companion.endswith(".bin"):
                shutil.copy(os.path.join(exports, companion), project)
        for extension in FORMATS:
            probes = [{"animation": animation or references[case]["animations"][0], "part": part,
                       "time": at, "points": [rest for rest, _ in points],
                       "posed": [posed for _, posed in points]}
                      for animation, part, at, points in probes_of(expected[case], extension)]
            request["scenes"].append({"file": f"{case}.{extension}", "probes": probes})

    with open(os.path.join(work, "editor.log"), "w") as log:
        missing = import_folder(godot, project, log)
    imported_at = time.monotonic()
    request_path = os.path.join(work, "request.json")
    report_path = os.path.join(work, "report.json")
    with open(request_path, "w") as f:
        json.dump(request, f)
    env = dict(hermetic_environment(work), RIGMESH_GODOT_REQUEST=request_path,
               RIGMESH_GODOT_REPORT=report_path)
    with open(os.path.join(work, "report.log"), "w") as log:
        subprocess.run(godot_command(godot, project, "-s", "report_scenes.gd"), env=env,
                       stdout=log, stderr=subprocess.STDOUT, timeout=600)
    if not os.path.exists(report_path):
        print(f"run_godot: report_scenes.gd wrote no report; see {work}/report.log")
        return 1
    with open(report_path) as f:
        report = json.load(f)
    print(f"run_godot: Godot {report['godot']}; import {imported_at - started:.1f} s, "
          f"report {time.monotonic() - imported_at:.1f} s (logs in {work})")

    checks = Checks()
    checks.check(not missing, "the editor imported every file" + (": not " + ", ".join(missing)
                                                                  if missing else ""))
    for entry in request["scenes"]:
        file = entry["file"]
        case = file.rsplit(".", 1)[0]
        scene = report["scenes"].get(file, {"loaded": False})
        for probe, asked in zip(scene.get("probes", []), entry["probes"]):
            probe["part"] = asked["part"]
            probe["expected_rest"] = asked["points"]
            probe["expected_posed"] = asked["posed"]
        check_file(checks, file, scene, references[case], expected[case]["model_size"])
    print(f"run_godot: {checks.passed} passed, {checks.failed} failed")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
