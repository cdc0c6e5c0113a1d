#!/usr/bin/env bash
# PackageInstallsAndRuns: builds the .deb from a configured
# build tree, unpacks it into a scratch root (dpkg -x, no root needed) and
# runs what it installed from there: `rigmesh --version`, a `rigmesh build`,
# and `rigmesh-studio --screenshot` under Xvfb; checks the desktop entry,
# the MIME type, the icons, the AppStream metainfo (appstreamcli validate)
# the manual pages and the translations (--help in German and Spanish); and
# runs lintian, which must report no error.
# usage: test-package.sh BUILD_DIR SKETCH.json
set -euo pipefail
build="$1"
sketch="$2"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

fail() { echo "FAIL: $*"; exit 1; }

echo "== cpack"
(cd "$build" && cpack -G DEB -B "$scratch/out" >"$scratch/cpack.log" 2>&1) ||
    { cat "$scratch/cpack.log"; fail "cpack"; }
deb="$(ls "$scratch"/out/rigmesh-studio_*.deb)"
echo "package: $(basename "$deb") ($(du -h "$deb" | cut -f1))"
dpkg-deb --info "$deb" | sed -n '/Package:/,$p'

echo "== unpacked into a scratch root"
root="$scratch/root"
dpkg -x "$deb" "$root"
for path in usr/bin/rigmesh usr/bin/rigmesh-studio \
            usr/share/applications/rigmesh-studio.desktop \
            usr/share/mime/packages/rigmesh-studio.xml \
            usr/share/metainfo/io.github.rigmesh.studio.metainfo.xml \
            usr/share/icons/hicolor/scalable/apps/rigmesh-studio.svg \
            usr/share/icons/hicolor/48x48/apps/rigmesh-studio.png \
            usr/share/icons/hicolor/256x256/apps/rigmesh-studio.png \
            usr/share/man/man1/rigmesh.1.gz usr/share/man/man1/rigmesh-studio.1.gz \
            usr/share/doc/rigmesh-studio/copyright usr/share/doc/rigmesh-studio/changelog.gz \
            usr/share/rigmesh-studio/translations/rigmesh_de.qm \
            usr/share/rigmesh-studio/translations/rigmesh_es.qm \
            usr/share/rigmesh-studio/translations/rigmesh_en.qm; do
    [ -e "$root/$path" ] || fail "the package has no /$path"
done
if dpkg -c "$deb" | grep -E 'test_|bench_|render-icon|include/' ; then
    fail "the package carries test, benchmark or build files"
fi

echo "== the installed programs"
version="$("$root/usr/bin/rigmesh" --version)"
echo "rigmesh --version: $version"
[[ "$version" == *"0."* ]] || fail "rigmesh --version printed '$version'"
(cd "$scratch" && "$root/usr/bin/rigmesh" build "$sketch" -o part.glb) || fail "rigmesh build"
[ -s "$scratch/part.glb" ] || fail "rigmesh build wrote nothing"
xvfb-run -a -s "-screen 0 1400x900x24" env QT_QPA_PLATFORM=xcb LIBGL_ALWAYS_SOFTWARE=1 \
    HOME="$scratch/home" "$root/usr/bin/rigmesh-studio" --screenshot "$scratch/studio.png" ||
    fail "rigmesh-studio --screenshot"
[ -s "$scratch/studio.png" ] || fail "no screenshot"
# The installed studio finds its installed translations and follows the
# system's language (no preference saved in this scratch home).
for spoken in de_DE:Silhouette es_ES:silueta; do
    locale="${spoken%%:*}"
    help="$(env QT_QPA_PLATFORM=offscreen HOME="$scratch/home" LANGUAGE="${locale%%_*}" \
        LC_ALL="$locale.UTF-8" "$root/usr/bin/rigmesh-studio" --help 2>&1)" || true
    echo "$help" | sed -n 2p
    # A here-string, not a pipe: under pipefail an early-exiting grep -q can
    # fail the pipeline; the whole help is printed when the word is missing.
    grep -q "${spoken#*:}" <<<"$help" ||
        { printf '%s\n' "$help"; fail "rigmesh-studio --help does not speak $locale"; }
done

echo "== desktop integration"
desktop="$root/usr/share/applications/rigmesh-studio.desktop"
grep -q '^Exec=rigmesh-studio %F$' "$desktop" || fail "desktop entry Exec"
# Its documents, and the meshes it imports when opened with one (widgets/CommandLineFiles).
grep -q '^MimeType=application/x-rigmesh;model/obj;model/gltf-binary;model/gltf+json;model/stl;$' \
    "$desktop" || fail "desktop entry MimeType"
grep -q 'glob pattern="\*.rigmesh"' "$root/usr/share/mime/packages/rigmesh-studio.xml" ||
    fail "MIME glob"
if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$desktop" || fail "desktop-file-validate"
fi
if command -v appstreamcli >/dev/null; then
    appstreamcli validate --no-net "$root/usr/share/metainfo/io.github.rigmesh.studio.metainfo.xml" ||
        fail "appstreamcli validate"
else
    fail "appstreamcli is not installed (Debian package appstream; run scripts/setup.sh)"
fi
zcat "$root/usr/share/man/man1/rigmesh.1.gz" | grep '^\.SH NAME' >/dev/null || fail "rigmesh(1)"

echo "== lintian"
if ! command -v lintian >/dev/null; then
    fail "lintian is not installed (Debian package lintian; run scripts/setup.sh)"
fi
lintian --tag-display-limit 0 "$deb" | tee "$scratch/lintian.log" || true
if grep -q '^E:' "$scratch/lintian.log"; then
    fail "lintian reports errors"
fi
echo "PASS"
