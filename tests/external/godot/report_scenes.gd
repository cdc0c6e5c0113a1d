# Loads each imported scene named in a request and reports what Godot made
# of it: every Skeleton (bone names and parents), every MeshInstance (skinned
# or not, its skeleton, its vertex count), the animations of every
# AnimationPlayer (names, lengths, key times), and for each probe the
# skinned positions of sample vertices at rest and at a time of an animation.
#
# usage: godot3 --audio-driver Dummy --path PROJECT -s report_scenes.gd
#   with the environment variables RIGMESH_GODOT_REQUEST (a JSON file) and
#   RIGMESH_GODOT_REPORT (the JSON file written).
# Request: {"scenes": [{"file": "star.glb", "probes": [{"animation": "clip",
#           "time": 0.5, "points": [[x, y, z], ...]}]}]}
# Report:  {"godot": version, "scenes": {"star.glb": {"loaded", "skeletons",
#           "meshes", "animations", "probes"}}}
#
# Skinning is evaluated here as Godot's renderer does it (linear blend
# skinning, at most 4 influences a vertex): a vertex v of a MeshInstance
# bound to a Skeleton goes to  M * sum_k w_k * G(b_k) * B_k * v, with M the
# MeshInstance's global transform, G a bone's global pose in the skeleton
# and B its bind pose from the mesh's Skin (without one, Godot binds to the
# rest: B = the inverse of the bone's global rest). A probe point is matched
# to the nearest vertex at rest.
extends SceneTree


func _initialize() -> void:
	var request = _read_json(OS.get_environment("RIGMESH_GODOT_REQUEST"))
	var report := {"godot": Engine.get_version_info()["string"], "scenes": {}}
	if typeof(request) != TYPE_DICTIONARY:
		printerr("report_scenes: cannot read the request")
		quit(2)
		return
	for entry in request["scenes"]:
		report["scenes"][entry["file"]] = _report_scene(entry)
	var out := File.new()
	if out.open(OS.get_environment("RIGMESH_GODOT_REPORT"), File.WRITE) != OK:
		printerr("report_scenes: cannot write the report")
		quit(2)
		return
	out.store_string(JSON.print(report, " "))
	out.close()
	quit(0)


func _read_json(path: String):
	var file := File.new()
	if file.open(path, File.READ) != OK:
		return null
	var parsed := JSON.parse(file.get_as_text())
	file.close()
	return parsed.result if parsed.error == OK else null


func _report_scene(entry: Dictionary) -> Dictionary:
	var path: String = "res://" + entry["file"]
	var packed = ResourceLoader.load(path) if ResourceLoader.exists(path) else null
	if packed == null or not packed is PackedScene:
		return {"loaded": false}
	var scene: Node = packed.instance()
	get_root().add_child(scene)
	var result := {"loaded": true, "skeletons": [], "meshes": [], "animations": [], "probes": []}
	var players := []
	_walk(scene, scene, result, players)
	for player in players:
		for name in player.get_animation_list():
			result["animations"].append(_describe_animation(name, player.get_animation(name)))
	for probe in entry.get("probes", []):
		result["probes"].append(_probe(scene, players, probe))
	get_root().remove_child(scene)
	scene.free()
	return result


func _walk(node: Node, scene: Node, result: Dictionary, players: Array) -> void:
	if node is Skeleton:
		var names := []
		var parents := []
		for bone in range(node.get_bone_count()):
			names.append(node.get_bone_name(bone))
			parents.append(node.get_bone_parent(bone))
		result["skeletons"].append({"path": str(scene.get_path_to(node)), "bones": names,
				"parents": parents})
	elif node is MeshInstance and node.mesh != null:
		var skeleton = _skeleton_of(node)
		var arrays: Array = node.mesh.surface_get_arrays(0) if node.mesh.get_surface_count() > 0 else []
		result["meshes"].append({
			"path": str(scene.get_path_to(node)),
			"name": node.name,
			"surfaces": node.mesh.get_surface_count(),
			"vertices": arrays[Mesh.ARRAY_VERTEX].size() if arrays.size() > 0 else 0,
			"weighted": arrays.size() > 0 and arrays[Mesh.ARRAY_WEIGHTS] != null,
			"skeleton": str(scene.get_path_to(skeleton)) if skeleton != null else "",
			"skin_binds": node.skin.get_bind_count() if node.skin != null else -1,
		})
	elif node is AnimationPlayer:
		players.append(node)
	for child in node.get_children():
		_walk(child, scene, result, players)


func _skeleton_of(mesh: MeshInstance):
	if mesh.skeleton == NodePath():
		return null
	var skeleton = mesh.get_node_or_null(mesh.skeleton)
	return skeleton if skeleton is Skeleton else null


func _describe_animation(name: String, animation: Animation) -> Dictionary:
	var times := {}
	for track in range(animation.get_track_count()):
		for key in range(animation.track_get_key_count(track)):
			times[stepify(animation.track_get_key_time(track, key), 0.0001)] = true
	var sorted := times.keys()
	sorted.sort()
	return {"name": name, "length": animation.length, "tracks": animation.get_track_count(),
			"key_times": sorted}


# The skinned positions of the mesh vertices nearest `points` (at rest), at
# rest and at the probe's time of its animation.
func _probe(scene: Node, players: Array, probe: Dictionary) -> Dictionary:
	var result := {"animation": probe["animation"], "time": probe["time"]}
	var player = null
	for candidate in players:
		if candidate.has_animation(probe["animation"]):
			player = candidate
	if player == null:
		result["error"] = "no animation " + probe["animation"]
		return result
	var meshes := []
	_skinned_meshes(scene, meshes)
	if meshes.empty():
		result["error"] = "no skinned mesh"
		return result
	player.stop(true)
	for mesh in meshes:
		_reset_pose(_skeleton_of(mesh))
	var candidates := []  # [mesh, vertex index, rest position]
	for mesh in meshes:
		var positions := _skinned_positions(mesh, null)
		for v in range(positions.size()):
			candidates.append([mesh, v, positions[v]])
	var matches := []
	for point in probe["points"]:
		var target := Vector3(point[0], point[1], point[2])
		var best = null
		var best_distance := INF
		for candidate in candidates:
			var distance: float = candidate[2].distance_to(target)
			if distance < best_distance:
				best_distance = distance
				best = candidate
		matches.append(best)
	player.play(probe["animation"])
	player.seek(probe["time"], true)
	var rest := []
	var posed := []
	for best in matches:
		rest.append(_vector(best[2]))
		posed.append(_vector(_skinned_positions(best[0], [best[1]])[0]))
	result["rest"] = rest
	result["posed"] = posed
	return result


func _skinned_meshes(node: Node, out: Array) -> void:
	if node is MeshInstance and node.mesh != null and _skeleton_of(node) != null:
		out.append(node)
	for child in node.get_children():
		_skinned_meshes(child, out)


func _reset_pose(skeleton: Skeleton) -> void:
	for bone in range(skeleton.get_bone_count()):
		skeleton.set_bone_pose(bone, Transform())


# Skinned positions of the vertices `only` (all when null) of the first
# surface, in the scene's frame.
func _skinned_positions(mesh: MeshInstance, only) -> Array:
	var skeleton: Skeleton = _skeleton_of(mesh)
	var arrays: Array = mesh.mesh.surface_get_arrays(0)
	var vertices = arrays[Mesh.ARRAY_VERTEX]
	var bones = arrays[Mesh.ARRAY_BONES]
	var weights = arrays[Mesh.ARRAY_WEIGHTS]
	var matrices := _bone_matrices(mesh, skeleton)
	var to_scene: Transform = mesh.global_transform
	var out := []
	var indices = only if only != null else range(vertices.size())
	for v in indices:
		var sum := Vector3()
		for k in range(4):
			var w: float = weights[4 * v + k]
			if w != 0.0:
				sum += w * (matrices[bones[4 * v + k]].xform(vertices[v]))
		out.append(to_scene.xform(sum))
	return out


# Per index in the mesh's bone array: global pose times bind pose.
func _bone_matrices(mesh: MeshInstance, skeleton: Skeleton) -> Array:
	var out := []
	if mesh.skin != null:
		for bind in range(mesh.skin.get_bind_count()):
			var bone: int = mesh.skin.get_bind_bone(bind)
			if bone < 0:
				bone = skeleton.find_bone(mesh.skin.call("get_bind_name", bind))
			out.append(skeleton.get_bone_global_pose(bone) * mesh.skin.get_bind_pose(bind))
		return out
	for bone in range(skeleton.get_bone_count()):
		out.append(skeleton.get_bone_global_pose(bone) * _global_rest(skeleton, bone).affine_inverse())
	return out


func _global_rest(skeleton: Skeleton, bone: int) -> Transform:
	var rest := skeleton.get_bone_rest(bone)
	var parent := skeleton.get_bone_parent(bone)
	while parent >= 0:
		rest = skeleton.get_bone_rest(parent) * rest
		parent = skeleton.get_bone_parent(parent)
	return rest


func _vector(v: Vector3) -> Array:
	return [v.x, v.y, v.z]
