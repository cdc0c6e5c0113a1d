// Bringing an older document file up to the current format before it is
// read (DocumentFile.cpp), one version step at a time, on the raw JSON tree.
// Only the structure is added here; every value is still checked by the
// reader afterwards.
//
//   2 -> 3 (the timeline): the document gains "timeline"
//     {startFrame, endFrame, framesPerSecond, currentFrame} and every part
//     "otherClips" []. The rate is the first part's clip rate (24 without
//     one, kept within the timeline's limits), the range runs from frame 0
//     to the last key's frame (at least 48), the current frame is 0.
//   4 -> 5 (imported rigs kept whole): nothing to add. Version 5 may hold
//     skeletons with disconnected bones, bone frames and mesh pieces, all
//     optional keys that an older file lacks: its skeletons are connected
//     trees, which read unchanged. The number says an older studio cannot
//     read what a version 5 file may hold.
//   5 -> 6 (weight notes as ids): a part's weights "warning", an English
//     sentence, becomes "warnings" [{"id", "args"}] (part/PartJson.cpp), so
//     the studio can show it in the user's language.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

namespace rigmesh::model {

// Migrates `root`, a document of format `version` (1 up to the current one),
// in place to the current version's structure. (1 -> 2, per-bone pose
// rotations, changes values, not structure: DocumentFile converts the read
// poses, pose/LegacyPose.h.)
void migrateDocument(nlohmann::json& root, std::int64_t version);

}  // namespace rigmesh::model
