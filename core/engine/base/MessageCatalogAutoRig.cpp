// The English templates of the engine messages about rigging an imported
// mesh (autorig/; see MessageCatalog.cpp: RIGMESH_TRANSLATABLE marks each for
// lupdate, in the context "EngineMessage"). An id not handled here is another
// file's.
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

const char* autoRigMessageTemplate(MessageId id) {
    switch (id) {
        case MessageId::AutoRigPartIsRigged:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "%1 already has a skeleton. Rig parts without one (imported meshes); to start "
                "a sketched part's rig again, use Recompute Weights or Rebuild.");
        case MessageId::AutoRigNoSurface:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has no surface to rig.");
        case MessageId::AutoRigTooFewFaces:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The mesh has only %1 usable faces; a rig needs a closed surface that bounds a "
                "volume.");
        case MessageId::AutoRigOpenBorder:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the mesh is open (%1 borders, the longest of %2 edges)");
        case MessageId::AutoRigSeveralPieces:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the mesh is %1 separate pieces");
        case MessageId::AutoRigSelfIntersecting:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 pairs of the mesh's faces cross each other");
        case MessageId::AutoRigNotManifold:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the mesh is not a manifold (more than two faces meet at an edge)");
        case MessageId::AutoRigSkeletonFailed:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "No skeleton could be found in the mesh: %1");
        case MessageId::AutoRigCancelled:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Rigging was cancelled.");
        case MessageId::AutoRigBoneTooShort:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The mesh is too small for a bone: its only bone would be %1 long, "
                "shorter than the shortest bone allowed (%2).");
        case MessageId::AutoRigRepairWelded:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "joined %1 vertices that sat at the same position (split seams)");
        case MessageId::AutoRigRepairDegenerate:
            return RIGMESH_TRANSLATABLE("EngineMessage", "removed %1 degenerate faces (no area)");
        case MessageId::AutoRigRepairDuplicateFaces:
            return RIGMESH_TRANSLATABLE("EngineMessage", "removed %1 duplicate faces");
        case MessageId::AutoRigRepairUnusedVertices:
            return RIGMESH_TRANSLATABLE("EngineMessage", "removed %1 vertices no face uses");
        case MessageId::AutoRigRepairNonManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "split %1 vertices where separate sheets touched");
        case MessageId::AutoRigRepairFlipped:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "turned the faces outward (they faced inward)");
        case MessageId::AutoRigRepairHoles:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "filled %1 small holes with %2 new vertices");
        case MessageId::AutoRigNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A vertex of the mesh is not a finite number: the file is corrupt.");
        case MessageId::AutoRigFaceOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A face of the mesh names vertex %1, but the mesh has only %2 vertices: the "
                "file is corrupt.");
        case MessageId::AutoRigOverMemoryBudget:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The mesh has %1 faces: rigging it would need more than the %2 MiB of memory "
                "allowed. Decimate it in your modelling tool (in Blender: the Decimate "
                "modifier) and import it again.");
        case MessageId::AutoRigLargeMesh:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the mesh has %1 vertices, too many to compute the skeleton on directly");
        case MessageId::AutoRigCoarseMesh:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the mesh's edges are long for its size (on average %1% of "
                "its diagonal), too coarse to compute the skeleton on directly");
        case MessageId::AutoRigProxyWrapped:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the skeleton and weights were computed on a closed proxy of %1 vertices "
                "wrapped around the mesh's %2 pieces; the mesh itself is kept as it was");
        case MessageId::AutoRigProxyApart:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "%1 pieces of the proxy lie apart from the body and follow its nearest bones");
        case MessageId::AutoRigPiecesFollowBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 small pieces (eyes, teeth, buttons) follow bone %2");
        case MessageId::AutoRigMorePiecesFollowBones:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 more small pieces follow one bone each");
        case MessageId::AutoRigHeldProps:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "%1 props held in a hand (a handle through the fist) rigged as the arm's "
                "chain on to their far end");
        case MessageId::AutoRigWornPieces:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "%1 pieces worn at a limb's end (horns on a helmet, a crest) ride on the limb's "
                "last bone");
        default:
            return nullptr;
    }
}

}  // namespace rigmesh
