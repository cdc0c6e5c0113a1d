// The native document file (.rigmesh): CBOR (RFC 8949) of one map
//   {"format": "rigmesh-studio-document", "version": 5, "nextPartId": n,
//    "timeline": {startFrame, endFrame, framesPerSecond, currentFrame},
//    "parts": [ {id, name, visible, placement, stroke, options, part: {...},
//                pose: {rotations: [[joint, w, x, y, z], ...], rootTranslation},
//                pinned: [joint, ...],
//                clip: {name, framesPerSecond,
//                       interpolation: "constant" | "linear" | "smooth",
//                       playback: "hold" | "loop" | "ping_pong",
//                       keys: [{time, pose: {rotations, rootTranslation}}, ...]},
//                otherClips: [clip, ...]} ]}
// where part holds everything of the engine Part: name, outline, mesh
// (vertices, faces), origins, mirror, skeleton (joints with ids, bones with
// ids, root, and since version 5 the attachments of disconnected bones'
// chains: {joints, bones}), skin weights and the known closest bones (bones by id since
// version 2; version 1 named them by position in the bone list, and reading
// converts them: part/PartJson.h). pose and pinned are
// optional when reading (a part without them loads in its rest pose, unpinned);
// their joint ids must be joints of the part's skeleton and the quaternions
// finite and non-zero. Pose rotations are per bone, keyed by the joint each
// bone ends at (the root: the whole skeleton), since version 2; version 1
// files stored one rotation per joint turning every bone leaving it, and
// load converted exactly (pose/LegacyPose.h): same bone transforms, same
// deformed surface. clip is optional too (absent: no keys at 24 frames per
// second); its keys are in time order, their poses checked like the pose.
// clip is the active clip, otherClips the part's other named clips; names
// are unique within a part. Files before version 3 (no timeline, no
// otherClips) are migrated on reading (DocumentMigration.h).
//
// Why CBOR: doubles are stored as IEEE binary64 (or binary32 when that is
// exact), so they round-trip bit for bit without decimal printing; meshes are
// about half the size of JSON; and nlohmann's maps have sorted keys, so the
// same document always gives the same bytes.
//
// Loading checks everything (format name, version, types, index ranges,
// array sizes) before building the document: a corrupt, truncated or newer
// file throws DocumentFileError with a message for the user and opens
// nothing. Every number must be finite; skin weights non-negative, summing to
// 1 per weighted vertex (every vertex of a rigged part); skeletons trees of
// chains (Skeleton::validate);
// placement rotations unit; edge lengths 0 or within checkBuildOptions()'s
// bounds. Sizes: every list is made from its own bytes (nesting is capped at
// 32 levels), and what is derived from single numbers is bounded (key times
// lie within +-1e6 s, Clip.h; an export samples at most 64 frames per key
// segment), so a small file cannot ask for gigabytes.
#pragma once

#include <QByteArray>
#include <QString>
#include <memory>

#include "base/Error.h"
#include "model/Document.h"

namespace rigmesh::model {

class DocumentFileError : public rigmesh::Error {
  public:
    using rigmesh::Error::Error;
};

namespace DocumentFile {

inline constexpr const char* kFormatName = "rigmesh-studio-document";
// 2: per-bone pose rotations (version 1 files are converted on loading);
// 3: the timeline and named clips (DocumentMigration.h adds them
// to older files);
// 4: skin weights, failed bones and known closest bones keyed by bone id
// (older files name them by position in the bone list; part/PartJson.h
// converts them on reading);
// 5: imported rigs kept whole: disconnected bones (skeleton "attachments"),
// the bones' rest frames ("boneFrames") and a shared skeleton's meshes
// ("meshPieces"), each written only when present, so older files read as
// they are (DocumentMigration.h);
// 6: skin weight notes as message ids and arguments, not English
// ("warnings"; DocumentMigration.h converts older files' "warning").
inline constexpr int kFormatVersion = 6;
inline constexpr const char* kSuffix = "rigmesh";

QByteArray toBytes(const DocumentContents& contents);
inline QByteArray toBytes(const Document& document) {
    return toBytes(document.contents());
}
// Throws DocumentFileError.
DocumentContents fromBytes(const QByteArray& bytes);

// Writes atomically (QSaveFile); does not touch the document's state.
// Throws DocumentFileError.
void write(const Document& document, const QString& path);
// write() then Document::markSaved(path).
void save(Document& document, const QString& path);
// A clean document with the file's contents and path. Throws DocumentFileError.
std::unique_ptr<Document> load(const QString& path, QObject* parent = nullptr);
// The contents only (recovery files, tests). Throws DocumentFileError.
DocumentContents read(const QString& path);

}  // namespace DocumentFile

}  // namespace rigmesh::model
