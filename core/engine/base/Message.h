// User-facing engine messages by id, so that the studio can show them in the
// user's language while the engine stays Qt-free and the CLI prints English.
// Each id has an English template with %1, %2, ... for its arguments
// (MessageCatalog.cpp); the studio translates the template, found by the
// same id, and fills in the same arguments (model/ErrorText).
#pragma once

#include <concepts>
#include <iosfwd>
#include <string>
#include <string_view>
#include <type_traits>
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

    // Documents, parts and commands (model/, model/commands/)
    DocumentNoSuchPart,
    DocumentPartHasNoJoint,
    DocumentPoseInvalid,
    DocumentKeyPoseInvalid,
    StartingPoseInvalid,
    NewPoseInvalid,
    StartingPoseForeignJoint,
    NewPoseForeignJoint,
    PoseNoSkeleton,
    BoneEditNoSkeleton,
    CutNoSurface,
    CutViewInvalid,
    MergeIntoItself,
    NamedPartHasNoJoint,
    MergePartsGone,
    NoSuchPart,
    PartGone,
    RigNoPart,
    RigPartChanged,
    RigPartsOutOfOrder,
    RecomputeNoPart,
    RecomputePartChanged,
    ImportNoMesh,
    ExportNoParts,
    ExportPartNotRigged,
    HistoryStepNotRecipe,
    DocumentNestedTooDeep,

    // Timeline, clips and keys (model/Timeline, model/PartClips, model/commands/)
    FrameRateOutOfRange,
    FrameRangeOutside,
    FrameRangeEmpty,
    FrameRangeTooLong,
    FrameOutside,
    ClipNameLength,
    ClipNameSpaces,
    ClipNameControlCharacters,
    ClipNameTwice,
    ClipNameTaken,
    NoClipNamed,
    DeleteOnlyClip,
    NoKeysToPaste,
    NoKeysToMove,
    KeyOffsetNotFinite,

    // Skin weights and skeletons (model/commands/, rig/, part/)
    PaintNoSkeleton,
    LockNoSkeleton,
    CleanupNoSkeleton,
    RecomputeNeedsSkeleton,
    RigCheckOptionsInvalid,
    WeightNamesMissingBone,
    WeightsNeedBone,
    WeightsNeedFiniteBone,
    MeshVertexPositionNotFinite,
    MeshTriangleMissingVertex,
    BoneToItself,
    MergeMissingJoints,
    RootCannotHang,
    SkeletonHasNoBone,
    RootWithoutJoints,
    SkeletonInvalid,
    SubdivisionInvalidResult,
    DecimationInvalidResult,
    PoseDemoNeedsBones,
    AutoRigFlowGaveNoCurve,
    AutoRigCurveTooShort,
    AutoRigFlowContracted,
    AutoRigTooFewVertices,
    AutoRigNoExtent,

    // Building surfaces (axis/, surface/, geometry/)
    OutlineNotElongated,
    PatchBoundaryTooShort,
    EdgeLengthMustBePositive,
    PatchTooManyRows,
    PatchTooManyPoints,
    SmoothingNeedsAnchor,
    PartEdgeLengthNotPositive,
    PartSurfaceNotManifold,
    PartSurfaceHasHole,
    CutSurfaceNotManifold,
    TargetSurfaceNotManifold,
    TargetSurfaceHasHole,
    DraggedSurfaceNotManifold,
    DraggedSurfaceHasHole,
    MeshSurfaceNotManifold,
    MeshSurfaceHasHole,

    // Mesh files (mesh/MeshReader, mesh/PlyReader, mesh/MeshWriter, mesh/MeshChecks)
    MeshFileCannotOpen,
    MeshFileReadFailed,
    MeshFileTypeUnsupported,
    MeshLineVertexCoordinates,
    MeshLineFaceCorners,
    ObjFaceVertexUndefined,
    MeshLineNotANumber,
    MeshLineNotAnInteger,
    MeshLineInvalidCount,
    OffEndsBeforeHeader,
    OffEndsBeforeCounts,
    OffEndsBeforeVertex,
    OffEndsBeforeFace,
    OffNoHeader,
    OffNoCounts,
    OffFaceCornerCount,
    OffFaceVertexOutOfRange,
    PlyNoMagic,
    PlyNoEndHeader,
    PlyNoFormat,
    PlyHeaderUnknownType,
    PlyHeaderUnknownFormat,
    PlyHeaderNotAnInteger,
    PlyHeaderInvalidCount,
    PlyHeaderListCountType,
    PlyHeaderMalformedProperty,
    PlyHeaderUnexpected,
    PlyTruncatedIn,
    PlyNotANumber,
    PlyListLengthOutOfRange,
    PlyVertexIndexOutOfRange,
    PlyFaceCorners,
    PlyCoordinateNotFinite,
    PlyNoXyz,
    PlyTwoVertexElements,
    PlyNoVertexIndices,
    PlyElementTooLarge,
    PlyNoVertexElement,
    PlyFaceVertexOutOfRange,
    MeshWriteVertexNotFinite,
    MeshWriteFaceMissingVertex,
    MeshVertexNotFinite,
    MeshFaceVertexMissing,

    // Sketch files (sketch/Sketch, sketch/SvgSketch)
    SketchCoordinateNotNumber,
    SketchNotJson,
    SketchNumberOutOfRange,
    SketchNotObject,
    SketchNoPoints,
    SketchPointNotPair,
    SketchFileTypeUnknown,
    SketchFileUnreadable,
    SketchFileReadFailed,
    SketchNotSvg,
    SketchNoSvgRoot,
    SketchSvgNoStroke,
    SvgExpectedLetter,
    SvgExpectedName,
    SvgExpectedNumber,
    SvgNumberOutOfRange,
    SvgExpectedArcFlag,
    SvgPathWithoutMoveto,
    SvgUnknownPathCommand,
    SvgOddCoordinateCount,
    SvgUnknownTransform,
    SvgTransformWithoutOpening,
    SvgTransformWithoutClosing,

    // Exports (io/)
    ExportGltfInvalidJson,
    ExportGltfUnknownComponentType,
    ExportGltfAccessorOutside,
    ExportGltfBufferViewOutside,
    ExportGltfNoBuffer,
    ExportColladaInvalidXml,
    ExportAnimationOfNothing,
    ExportAnimationWithoutKeys,
    ExportAnimationNoNode,
    ExportUnitScaleNotPositive,
    ExportUnknownFormat,
    ExportRigNoSkeleton,
    RigJsonVertexNotFinite,
    RigJsonJointNotFinite,
    RigJsonWeightNotFinite,
    FbxRepairNotBinary,
    FbxRepairNoRecords,
    FbxRepairRecordPastEnd,
    FbxRepairNestedOutOfRange,
    ExportVertexNotFinite,
    ExportNormalNotFinite,
    ExportBindMatrixNotFinite,
    ExportBoneWeightNotFinite,
    ExportNodeTransformNotFinite,
    ExportKeyNotFinite,
    ExportDurationNotFinite,
    ExportGltfNoBin,

    // Recipes (model/recipe/)
    RecipeNoPartAtIndexOfOne,
    RecipeNoPartAtIndex,
    RecipePartReference,
    RecipeNoPartNamed,
    RecipePartNameAmbiguous,
    RecipePartHasNoBone,
    RecipePartHasNoJoint,
    RecipePartHasNoSkeleton,
    RecipePaintMode,
    RecipeFalloff,
    RecipeLockedBones,
    RecipeDabNeedsCenter,
    RecipeStepNeedsCenter,
    RecipeDabsOrCenter,
    RecipeDabsList,
    RecipeWholeNumber,
    RecipeStepNeeds,
    RecipeStrokeOrPoints,
    RecipeTargetOrRotations,
    RecipeGoesWithRotations,
    RecipeReach,
    RecipeReachGoesWithTarget,
    RecipeInterpolation,
    RecipePlayback,
    RecipeTimes,
    RecipeKeys,
    RecipeKeyFields,
    RecipeWholeFrame,
    RecipeMergeMode,
    RecipeReskin,
    RecipePlaneOrStroke,
    RecipePlaneFields,
    RecipeViewFields,
    RecipeCutStrokeTooShort,
    RecipeJoinStyle,
    RecipeTwoNames,
    RecipePartsList,
    RecipeUnknownCommand,
    RecipeUnknownField,
    RecipeNotARecipe,
    RecipeNoVersion,
    RecipeVersionTooNew,
    RecipeNoSteps,
    RecipeNotJson,
    RecipeNumberOutOfRange,
    RecipeCannotRead,
    RecipeCannotWriteFolder,
    RecipeCannotWrite,
    RecipeEdgeLength,
    RecipePointsList,
    RecipeRotationsObject,
    RecipeRotationsJointTwice,
    RecipeFieldNumberList,
    RecipeFieldQuaternionList,
    RecipeFieldObject,
    RecipeFieldUnknown,
    RecipeFieldNumber,
    RecipeFieldFiniteNumber,
    RecipeFieldTrueOrFalse,
    RecipeFieldText,
    RecipeFieldZeroQuaternion,
    RecipeFieldNotJointId,
    RecipeFieldJointIdType,

    // Skin weight notes (rig/BoneHeatSolver): warnings a part keeps with its weights
    WeightsBoneUnsolved,
    WeightsBonesUnsolved,
    WeightsNotFactored,
    WeightsVerticesSeeNoBone,

    // Reading saved data (base/JsonRead, part/PartJson): what is wrong in a
    // document, recipe or sketch file. Fields are named by their path in the
    // file ("skeleton" "joints" "ids"), which reads the same in every language.
    UntranslatedText,
    DataNotMap,
    DataFieldMissing,
    DataNotList,
    DataNotNumber,
    DataNotFinite,
    DataNotBoolean,
    DataNotText,
    DataWrongLength,
    DataNotInteger,
    DataOutOfRange,
    DataEndsEarly,
    DataMalformedAt,
    DataNumberTooLarge,
    DataWrongType,
    DataMalformed,
    DataUnknownWeightNote,
    DataWeightNoteArguments,
    DataMissingBoneAtIndex,
    DataMissingBone,
    DataNotPerVertex,
    DataMalformedEntry,
    DataNegative,
    DataWeightSum,
    DataJointCountsDiffer,
    DataJointIdRepeated,
    DataBoneCountsDiffer,
    DataBoneIdRepeated,
    DataBoneMissingJoint,
    DataRootNotJoint,
    DataAttachmentCountsDiffer,
    DataAttachmentMissing,
    DataSkeletonNotTree,
    DataFaceMissingVertex,
    DataUnknownOriginKind,
    DataMirrorMissingVertex,
    DataWeightsMissing,
    DataBoneNameMalformed,
    DataBoneNameMissingBone,
    DataLockedBoneMissing,
    DataBoneFrameMalformed,
    DataBoneFrameInvalid,
    DataPartInvalid,

    // Recipe steps (model/recipe/RecipeRunner)
    RecipeStepFailed,
    RecipeStepNotObject,
    RecipeStepNoCommand,
    RecipeStepCommandNotText,

    // What keeps a part or a skeleton from being valid (part/PartValidate,
    // rig/SkeletonHierarchy): Part::validate(), Skeleton::validate()
    PartVertexNotFinite,
    PartFaceMissingVertex,
    PartFaceRepeatsVertex,
    PartOutlineNotFinite,
    PartOriginsNotPerVertex,
    PartMirrorNotPerVertex,
    PartMirrorMissingVertex,
    PartWeightsNotPerVertex,
    PartWeightsCount,
    PartWeightsMissingBone,
    PartWeightsOutOfOrder,
    PartWeightsNotPositive,
    PartWeightsSum,
    PartClosestBonesCount,
    PartClosestBonesMissingBone,
    PartClosestBonesOutOfOrder,
    PartClosestBonesNotPositive,
    PartBonesWithoutJoints,
    PartUnriggedHasWeights,
    PartFailedBoneMissing,
    PartBoneNameInvalid,
    PartLockedBoneMissing,
    PartBoneFrameInvalid,
    PartPiecesDoNotFit,
    PartPieceUsesOthersVertex,
    PartPiecesDoNotCover,
    PartSurfaceBoundaryEdges,
    PartSurfaceNotAManifold,
    PartSurfaceNotOriented,
    SkeletonNoJoints,
    SkeletonJointIdTwice,
    SkeletonJointNotFinite,
    SkeletonBoneIdTwice,
    SkeletonNoRoot,
    SkeletonRootMissing,
    SkeletonBoneMissingJoint,
    SkeletonBoneJoinsItself,
    SkeletonBoneZeroLength,
    SkeletonCycle,
    SkeletonHangingJointMissing,
    SkeletonRootHangs,
    SkeletonHangsFromMissingBone,
    SkeletonOneChainHangsTwice,
    SkeletonHangsInRootChain,
    SkeletonNotConnected,
    SkeletonNotConnectedLoose,
    SkeletonHangsFromOwnChain,
    SkeletonChainsHangInALoop,

    Count  // not a message: the number of ids
};

// A message: its id and its arguments, already text, and the messages that
// fill the template's markers after the arguments' own, each put in the
// reader's language first ("The document is corrupt: %1." with what is wrong
// as a message of its own).
struct Message {
    MessageId id = MessageId::None;
    std::vector<std::string> args;
    std::vector<Message> nested = {};

    friend bool operator==(const Message&, const Message&) = default;
};

// The English template of `id`, e.g. "The part has no bone %1." (empty for None).
const char* messageTemplate(MessageId id);

// `text` with %1 .. %9 replaced by `args` in one pass, so an argument that
// itself holds "%2" stays as it is; a missing argument leaves its marker.
// The result has the shape of every message (base/MessageText.h: one line,
// quoted names elided), whatever the arguments hold.
std::string fillMessage(std::string_view text, const std::vector<std::string>& args);

// The English text of `message`, nested messages included.
std::string englishText(const Message& message);
// The English texts of `messages` on one line, separated by spaces.
std::string englishText(const std::vector<Message>& messages);

// Its English text, e.g. in a test's failure output.
std::ostream& operator<<(std::ostream& out, const Message& message);

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

// A message from its id and arguments, in the template's order: text and
// integers become arguments; a Message (e.g. a part's first problem inside
// the refusal it caused) fills a marker after them, in the reader's
// language, so messages come last.
template <class... Args>
constexpr bool messagesComeLast() {
    bool seenMessage = false, inOrder = true;
    ((std::is_same_v<Args, Message> ? void(seenMessage = true)
                                    : void(inOrder = inOrder && !seenMessage)),
     ...);
    return inOrder;
}

template <class... Args>
Message makeMessage(MessageId id, const Args&... args) {
    static_assert(messagesComeLast<Args...>(), "nested messages fill the last markers");
    Message message{id, {}};
    [[maybe_unused]] const auto add = [&message](const auto& argument) {
        if constexpr (std::is_same_v<std::decay_t<decltype(argument)>, Message>)
            message.nested.push_back(argument);
        else
            message.args.push_back(messageArgument(argument));
    };
    (add(args), ...);
    return message;
}

}  // namespace rigmesh
