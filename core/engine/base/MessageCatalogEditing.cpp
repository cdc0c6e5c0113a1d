// The English templates of the engine messages about documents, commands, the
// timeline, clips, skeletons, skin weights and surfaces (see
// MessageCatalog.cpp: RIGMESH_TRANSLATABLE marks each for lupdate, in the
// context "EngineMessage"). An id not handled here is another file's.
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

const char* editingMessageTemplate(MessageId id) {
    switch (id) {
        // Documents, parts and commands (model/, model/commands/)
        // Skin weight notes (rig/BoneHeatSolver)
        case MessageId::WeightsBoneUnsolved:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Skin weights could not be solved for bone %1; "
                                        "nearest-bone weights are used instead.");
        case MessageId::WeightsBonesUnsolved:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Skin weights could not be solved for bones %1; "
                                        "nearest-bone weights are used instead.");
        case MessageId::WeightsNotFactored:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skin weights' heat system could not be factored; "
                                        "every bone uses nearest-bone weights instead.");
        case MessageId::WeightsVerticesSeeNoBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 vertices see no bone from inside the shape and are "
                                        "heated by their nearest bone.");
        case MessageId::DocumentNoSuchPart:
            return RIGMESH_TRANSLATABLE("EngineMessage", "No part with id %1 in the document.");
        case MessageId::DocumentPartHasNoJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Part %1 has no joint %2.");
        case MessageId::DocumentPoseInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The pose of part %1 has a non-finite or zero rotation or translation.");
        case MessageId::DocumentKeyPoseInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The key at %1 s of part %2 has a non-finite or zero rotation or translation.");
        case MessageId::StartingPoseInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The starting pose of part %1 has a non-finite or zero rotation or translation.");
        case MessageId::NewPoseInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The new pose of part %1 has a non-finite or zero rotation or translation.");
        case MessageId::StartingPoseForeignJoint:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The starting pose names joint %1, which part %2 does not have.");
        case MessageId::NewPoseForeignJoint:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The new pose names joint %1, which part %2 does not have.");
        case MessageId::PoseNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no skeleton to pose.");
        case MessageId::BoneEditNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no skeleton to edit.");
        case MessageId::CutNoSurface:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no surface to cut.");
        case MessageId::CutViewInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut's view needs a direction and an up that is not along it.");
        case MessageId::MergeIntoItself:
            return RIGMESH_TRANSLATABLE("EngineMessage", "A part cannot be merged into itself.");
        case MessageId::NamedPartHasNoJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has no joint %2");
        case MessageId::MergePartsGone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The parts to merge are no longer in the document.");
        case MessageId::NoSuchPart:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no such part.");
        case MessageId::PartGone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part is no longer in the document.");
        case MessageId::RigNoPart:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no part to rig.");
        case MessageId::RigPartChanged:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The part changed while it was rigged; nothing was changed.");
        case MessageId::RigPartsOutOfOrder:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The parts to rig together must be given in document order, once each.");
        case MessageId::RecomputeNoPart:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "There is no part to recompute the weights of.");
        case MessageId::RecomputePartChanged:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The part changed while its weights were recomputed; nothing was changed.");
        case MessageId::ImportNoMesh:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 holds no mesh to import");
        case MessageId::ExportNoParts:
            return RIGMESH_TRANSLATABLE("EngineMessage", "there are no parts to export");
        case MessageId::ExportPartNotRigged:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"%1\" is not rigged yet: export it as OBJ, or hide it and export the visible "
                "parts");
        case MessageId::HistoryStepNotRecipe:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The history step \"%1\" cannot be written as a recipe step.");
        case MessageId::DocumentNestedTooDeep:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "lists and maps are nested more than %1 levels deep");

        // Timeline, clips and keys (model/Timeline, model/PartClips, model/commands/)
        case MessageId::FrameRateOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The frame rate must be between %1 and %2 frames per second.");
        case MessageId::FrameRangeOutside:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The frame range must lie within frames 0 to %1.");
        case MessageId::FrameRangeEmpty:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The frame range must end after it starts.");
        case MessageId::FrameRangeTooLong:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The frame range is longer than a clip can be.");
        case MessageId::FrameOutside:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Frame %1 is outside frames 0 to %2.");
        case MessageId::ClipNameLength:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A clip name must have 1 to %1 characters.");
        case MessageId::ClipNameSpaces:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A clip name must not start or end with a space.");
        case MessageId::ClipNameControlCharacters:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A clip name must not hold control characters.");
        case MessageId::ClipNameTwice:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has two clips named \"%1\".");
        case MessageId::ClipNameTaken:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 already has a clip named \"%2\".");
        case MessageId::NoClipNamed:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has no clip named \"%2\".");
        case MessageId::DeleteOnlyClip:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "%1 has only this clip: a part keeps one clip (delete its keys instead).");
        case MessageId::NoKeysToPaste:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There are no keys to paste.");
        case MessageId::NoKeysToMove:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There are no keys to move.");
        case MessageId::KeyOffsetNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The keys' offset is not a finite number of seconds.");

        // Skin weights and skeletons (model/commands/, rig/, part/)
        case MessageId::PaintNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The part has no skeleton, so it has no weights to paint.");
        case MessageId::LockNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The part has no skeleton, so it has no weights to lock.");
        case MessageId::CleanupNoSkeleton:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The part has no skeleton, so it has no weights to clean up.");
        case MessageId::RecomputeNeedsSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Only a part with a skeleton has weights to recompute.");
        case MessageId::RigCheckOptionsInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Check Rig needs at least one influence and a positive tolerance.");
        case MessageId::WeightNamesMissingBone:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A skin weight refers to bone %1, which the skeleton does not have.");
        case MessageId::WeightsNeedBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Skin weights need at least one bone.");
        case MessageId::WeightsNeedFiniteBone:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Skin weights need at least one bone with finite end points.");
        case MessageId::MeshVertexPositionNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The mesh has a vertex with a non-finite position.");
        case MessageId::MeshTriangleMissingVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The mesh has a triangle that refers to a missing vertex.");
        case MessageId::BoneToItself:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A bone cannot connect joint %1 to itself.");
        case MessageId::MergeMissingJoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Only existing joints can be merged.");
        case MessageId::RootCannotHang:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The root joint %1 cannot hang from a bone.");
        case MessageId::SkeletonHasNoBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The skeleton has no bone %1.");
        case MessageId::RootWithoutJoints:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot choose a root for a skeleton without joints.");
        case MessageId::SkeletonInvalid:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the skeleton of this shape is invalid: %1");
        case MessageId::SubdivisionInvalidResult:
            return RIGMESH_TRANSLATABLE("EngineMessage", "subdividing '%1' failed: %2");
        case MessageId::DecimationInvalidResult:
            return RIGMESH_TRANSLATABLE("EngineMessage", "decimating '%1' failed: %2");
        case MessageId::PoseDemoNeedsBones:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the pose demo needs a part with bones");
        case MessageId::AutoRigFlowGaveNoCurve:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "No skeleton could be found in the mesh: the flow gave no curve.");
        case MessageId::AutoRigCurveTooShort:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "No skeleton could be found in the mesh: the curve is too short for a bone.");
        case MessageId::AutoRigFlowContracted:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "No skeleton could be found in the mesh: the flow contracted it to a point.");
        case MessageId::AutoRigTooFewVertices:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "No skeleton could be found in the mesh: the mesh has too few vertices.");
        case MessageId::AutoRigNoExtent:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "No skeleton could be found in the mesh: the mesh has no extent.");

        // Building surfaces (axis/, surface/, geometry/)
        case MessageId::OutlineNotElongated:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the outline has no elongated part to inflate: draw a longer shape");
        case MessageId::PatchBoundaryTooShort:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a patch boundary needs at least three points");
        case MessageId::EdgeLengthMustBePositive:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the target edge length must be positive");
        case MessageId::PatchTooManyRows:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the edge length is too small for this patch: %1 lattice rows or columns");
        case MessageId::PatchTooManyPoints:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "the edge length is too small for this patch: %1 lattice points");
        case MessageId::SmoothingNeedsAnchor:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "least-squares smoothing needs at least one anchored vertex");
        case MessageId::PartEdgeLengthNotPositive:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The target edge length must be 0 (automatic) or a positive length.");
        case MessageId::PartSurfaceNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface of the part is not a manifold.");
        case MessageId::PartSurfaceHasHole:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The surface of the part has a hole, so it does not bound a volume.");
        case MessageId::CutSurfaceNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface of the cut is not a manifold.");
        case MessageId::TargetSurfaceNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface of the target part is not a manifold.");
        case MessageId::TargetSurfaceHasHole:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The surface of the target part has a hole, so it does not bound a volume.");
        case MessageId::DraggedSurfaceNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface of the dragged part is not a manifold.");
        case MessageId::DraggedSurfaceHasHole:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The surface of the dragged part has a hole, so it does not bound a volume.");
        case MessageId::MeshSurfaceNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface of the mesh is not a manifold.");
        case MessageId::MeshSurfaceHasHole:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The surface of the mesh has a hole, so it does not bound a volume.");
        default:
            return nullptr;
    }
}

}  // namespace rigmesh
