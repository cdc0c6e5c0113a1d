// User-facing engine messages by id, so that the studio can show them in the
// user's language while the engine stays Qt-free and the CLI prints English.
// Each id has an English template with %1, %2, ... for its arguments
// (MessageCatalog.cpp); the studio translates the template, found by the
// same id, and fills in the same arguments (model/ErrorText).
#pragma once

#include <concepts>
#include <string>
#include <string_view>
#include <vector>

namespace rigmesh {

enum class MessageId {
    None,  // a message without an id: its English text is all there is

    // Drawing a stroke (sketch/StrokeCleaner, geometry/ConstrainedTriangulation, axis/ChordalAxis)
    StrokeNotFinite,
    StrokeOneDistinctPoint,
    StrokeTooFewDistinctPoints,
    StrokeRepeatsPositions,
    StrokeTooLong,
    StrokeOnALine,
    StrokeCrossesItselfNear,
    StrokeNoWidth,
    StrokeTooLarge,
    OutlineTouchesItself,
    OutlineCrossesItself,
    OutlineTooFewPoints,
    OutlineRepeatedPoints,
    OutlineNoArea,
    OutlineTooSimple,

    // Building the surface (pipeline/SurfaceLimits, surface/)
    SketchSizeOutOfRange,
    SketchTooFarFromOrigin,
    EdgeLengthTooSmall,
    SurfaceNotFinite,
    SurfaceDegenerateFaces,
    EdgeLengthNotPositive,
    SurfaceSmoothingNotFactored,
    SurfaceSmoothingNoSolution,
    SurfaceSelfIntersecting,
    PartHasNoSketch,

    // Merging (merge/)
    MergeNeedsRiggedParts,
    MergeInvalidResult,
    MergeNoDraggedJoint,
    MergeNoTargetJoint,
    MergeNoTargetBone,
    MergeJointsCoincide,
    MergeSelfIntersecting,
    MergeNotManifold,
    MergePartsApart,
    MergePartInside,
    LocalWeightsUnsolved,
    MergeTargetNotSolid,
    MergeDraggedNotSolid,
    MergeTargetIntersectsItself,
    MergeDraggedIntersectsItself,
    MergeJointsTooClose,

    // Cutting and bone edits (cut/)
    CutNeedsRiggedPart,
    CutNeedsPlane,
    CutStrokeNotFinite,
    CutMissesPart,
    CutCrossesTwice,
    CutPiecesOnOneSide,
    CutPieceWithoutBone,
    CutPieceNotOneTree,
    CutPatchWeightsUnsolved,
    CutInvalidPiece,
    CutStrokeTooShort,
    CutStrokeClosed,
    BoneEditInvalidResult,
    PartHasNoSkeleton,
    PartHasNoBone,
    SplitTooCloseToJoint,
    SplitBoneLeadsNothing,
    DeleteOnlyBone,
    BoneNotConnected,
    ConnectBoneAlreadyConnected,
    ConnectBoneHasNoParent,
    CutPartNotSolid,
    CutPieceBoneTooShort,
    SplitBoneTooShort,
    DeleteLeavesShortBone,

    // Posing and keys (pose/)
    IkTargetNotFinite,
    PoseNeedsJoints,
    PoseNeedsRoot,
    SkeletonHasNoJoint,
    PoseRotationInvalid,
    PoseTranslationNotFinite,
    KeyAlreadyAt,
    NoKeyExactlyAt,
    NoKeyAt,
    NoKeyToMove,
    NoKeyToDelete,
    ClipHasNoKeys,
    ClipPlayedWithoutKeys,
    KeyPoseInvalid,
    KeyTimeNotFinite,
    KeyTimeNegative,
    KeyTimeTooLate,
    ClipFrameRateInvalid,

    // Weight painting and clean-ups (part/WeightPaint, part/WeightCleanup)
    PaintNoSuchBone,
    PaintBoneLocked,
    PaintLockedNoSuchBone,
    PaintBrushInvalid,
    PaintViewDirectionInvalid,
    PaintMirrorAsymmetric,
    CleanThresholdOutOfRange,
    LimitNeedsOneInfluence,
    SmoothAllOutOfRange,

    // Files and exports (base/StagedFile, io/, part/PartSubdivision, part/PartDecimation)
    CannotWriteFile,
    WriteFolderMissing,
    WriteTargetIsFolder,
    WriteReadOnly,
    WriteCannotCreate,
    WriteDiskFull,
    WritePermissionsLost,
    ExportNoPart,
    ExportPartWithoutSurface,
    ExportWeightsMismatch,
    ExportKeysTooClose,
    SubdivisionLevelsOutOfRange,
    SubdivisionTooManyVertices,
    DecimationTooFewFaces,
    DecimationNotManifold,

    // Importing files (model/ImportReader, io/SceneImport)
    ImportNoSuchFile,
    ImportNotAFile,
    ImportReaderMissing,
    ImportReaderNotStarted,
    ImportTimedOut,
    ImportReaderCrashed,
    ImportOutOfMemory,
    ImportReaderFailed,
    ImportBadData,
    ImportPartUnusable,
    ImportUnreadable,
    ImportUnknownFormat,
    ImportIncomplete,
    ImportNoTriangleMesh,

    // Rigging an imported mesh (autorig/)
    AutoRigPartIsRigged,
    AutoRigNoSurface,
    AutoRigTooFewFaces,
    AutoRigOpenBorder,
    AutoRigSeveralPieces,
    AutoRigSelfIntersecting,
    AutoRigNotManifold,
    AutoRigSkeletonFailed,
    AutoRigCancelled,
    AutoRigBoneTooShort,
    AutoRigRepairWelded,
    AutoRigRepairDegenerate,
    AutoRigRepairDuplicateFaces,
    AutoRigRepairUnusedVertices,
    AutoRigRepairNonManifold,
    AutoRigRepairFlipped,
    AutoRigRepairHoles,
    AutoRigNotFinite,
    AutoRigFaceOutOfRange,
    AutoRigOverMemoryBudget,
    AutoRigLargeMesh,
    AutoRigProxyWrapped,
    AutoRigProxyApart,
    AutoRigPiecesFollowBone,
    AutoRigMorePiecesFollowBones,

    Count  // not a message: the number of ids
};

// A message: its id and its arguments, already text.
struct Message {
    MessageId id = MessageId::None;
    std::vector<std::string> args;
};

// The English template of `id`, e.g. "The part has no bone %1." (empty for None).
const char* messageTemplate(MessageId id);

// `text` with %1 .. %9 replaced by `args` in one pass, so an argument that
// itself holds "%2" stays as it is; a missing argument leaves its marker.
// The result has the shape of every message (base/MessageText.h: one line,
// quoted names elided), whatever the arguments hold.
std::string fillMessage(std::string_view text, const std::vector<std::string>& args);

// The English text of `message`.
std::string englishText(const Message& message);

// A number for a message: three significant digits ("0.000215", "1.5e+06").
std::string shortNumber(double value);

// Message arguments are text: integers are written in full, strings as they
// are. Other numbers are formatted by the caller, so the engine decides
// their precision; most use shortNumber.
inline std::string messageArgument(std::string text) {
    return text;
}
inline std::string messageArgument(const char* text) {
    return text;
}
template <std::integral Integer>
std::string messageArgument(Integer value) {
    return std::to_string(value);
}

}  // namespace rigmesh
