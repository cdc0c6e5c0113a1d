// The English templates of what keeps a part or a skeleton from being valid
// (Part::validate in part/PartValidate.cpp, Skeleton::validate in
// rig/SkeletonHierarchy.cpp): each is a sentence of its own, shown inside the
// refusal of the operation that found it (a cut, a merge, an import, a
// document that will not open). See MessageCatalog.cpp: RIGMESH_TRANSLATABLE
// marks each for lupdate, in the context "EngineMessage".
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

const char* validationMessageTemplate(MessageId id) {
    switch (id) {
        case MessageId::PartVertexNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Vertex %1 has a non-finite position.");
        case MessageId::PartFaceMissingVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Face %1 refers to a missing vertex.");
        case MessageId::PartFaceRepeatsVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Face %1 repeats a vertex.");
        case MessageId::PartOutlineNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The outline has a non-finite point.");
        case MessageId::PartOriginsNotPerVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The vertex origins do not have one entry per vertex.");
        case MessageId::PartMirrorNotPerVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The mirror map does not have one entry per vertex.");
        case MessageId::PartMirrorMissingVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The mirror map refers to a missing vertex.");
        case MessageId::PartWeightsNotPerVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skin weights do not have one entry per vertex.");
        case MessageId::PartWeightsCount:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skin weights have %1 entries for %2 vertices.");
        case MessageId::PartWeightsMissingBone:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The skin weights of vertex %1 name bone %2, which the skeleton does not have.");
        case MessageId::PartWeightsOutOfOrder:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skin weights of vertex %1 are not in bone order.");
        case MessageId::PartWeightsNotPositive:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The skin weights of vertex %1 hold a value that is not finite and positive.");
        case MessageId::PartWeightsSum:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skin weights of vertex %1 sum to %2, not 1.");
        case MessageId::PartClosestBonesCount:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The known closest bones have %1 entries for %2 vertices.");
        case MessageId::PartClosestBonesMissingBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The known closest bones of vertex %1 name bone %2, which "
                                        "the skeleton does not have.");
        case MessageId::PartClosestBonesOutOfOrder:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The known closest bones of vertex %1 are not in bone order.");
        case MessageId::PartClosestBonesNotPositive:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The known closest bones of vertex %1 hold a value that is "
                                        "not finite and positive.");
        case MessageId::PartBonesWithoutJoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The skeleton has bones but no joints.");
        case MessageId::PartUnriggedHasWeights:
            return RIGMESH_TRANSLATABLE("EngineMessage", "An unrigged part has skin weights.");
        case MessageId::PartFailedBoneMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The failed bones name a missing bone.");
        case MessageId::PartBoneNameInvalid:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A bone name is empty, repeated or names a missing bone.");
        case MessageId::PartLockedBoneMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Bone %1 is locked but the skeleton has no such bone.");
        case MessageId::PartBoneFrameInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "A bone frame is not a unit rotation or names a missing bone.");
        case MessageId::PartPiecesDoNotFit:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The mesh pieces do not fit the mesh.");
        case MessageId::PartPieceUsesOthersVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Mesh piece '%1' uses another piece's vertex.");
        case MessageId::PartPiecesDoNotCover:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The mesh pieces do not cover the mesh.");
        case MessageId::PartSurfaceBoundaryEdges:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The surface has %1 boundary edges.");
        case MessageId::PartSurfaceNotAManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The surface is not a manifold.");
        case MessageId::PartSurfaceNotOriented:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The surface is not consistently oriented.");
        case MessageId::SkeletonNoJoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The skeleton has no joints.");
        case MessageId::SkeletonJointIdTwice:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Two joints share the id %1.");
        case MessageId::SkeletonJointNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Joint %1 has a non-finite position.");
        case MessageId::SkeletonBoneIdTwice:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Two bones share the id %1.");
        case MessageId::SkeletonNoRoot:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The skeleton has no root joint.");
        case MessageId::SkeletonRootMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The root is joint %1, which does not exist.");
        case MessageId::SkeletonBoneMissingJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Bone %1 refers to joint %2, which does not exist.");
        case MessageId::SkeletonBoneJoinsItself:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Bone %1 connects joint %2 to itself.");
        case MessageId::SkeletonBoneZeroLength:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Bone %1 has zero length.");
        case MessageId::SkeletonCycle:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skeleton has a cycle: bone %1 closes a loop.");
        case MessageId::SkeletonHangingJointMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Joint %1 hangs from a bone but does not exist.");
        case MessageId::SkeletonRootHangs:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The root joint %1 hangs from a bone.");
        case MessageId::SkeletonHangsFromMissingBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Joint %1 hangs from bone %2, which does not exist.");
        case MessageId::SkeletonOneChainHangsTwice:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Joints %1 and %2 both hang from bones but are in one chain.");
        case MessageId::SkeletonHangsInRootChain:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Joint %1 hangs from a bone but is connected to the root's chain.");
        case MessageId::SkeletonNotConnected:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The skeleton is not connected: it has %1 separate components.");
        case MessageId::SkeletonNotConnectedLoose:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The skeleton is not connected: it has %1 separate "
                                        "components, %2 of them hanging from no bone.");
        case MessageId::SkeletonHangsFromOwnChain:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Joint %1 hangs from a bone of its own chain.");
        case MessageId::SkeletonChainsHangInALoop:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The chain of joint %1 hangs from chains that hang from it.");
        default:
            return nullptr;  // another file's
    }
}

}  // namespace rigmesh
