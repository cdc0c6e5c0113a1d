// The English templates of the engine messages about recipes (see
// MessageCatalog.cpp: RIGMESH_TRANSLATABLE marks each for lupdate, in the
// context "EngineMessage"). An id not handled here is another file's.
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

const char* recipeMessageTemplate(MessageId id) {
    switch (id) {
        // Recipes (model/recipe/)
        case MessageId::RecipeNoPartAtIndexOfOne:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "there is no part at index %1 (the document has %2 part)");
        case MessageId::RecipeNoPartAtIndex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "there is no part at index %1 (the document has %2 parts)");
        case MessageId::RecipePartReference:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"part\" must be a part's name or its index (from 0)");
        case MessageId::RecipeNoPartNamed:
            return RIGMESH_TRANSLATABLE("EngineMessage", "there is no part \"%1\"");
        case MessageId::RecipePartNameAmbiguous:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "%1 parts are named \"%2\"; refer to the part by its index");
        case MessageId::RecipePartHasNoBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "part \"%1\" has no bone %2");
        case MessageId::RecipePartHasNoJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "part \"%1\" has no joint %2");
        case MessageId::RecipePartHasNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage", "part \"%1\" has no skeleton");
        case MessageId::RecipePaintMode:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"mode\" must be \"add\", \"subtract\", \"replace\" or \"smooth\"");
        case MessageId::RecipeFalloff:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"falloff\" must be \"smooth\", \"linear\", \"sharp\" or \"constant\"");
        case MessageId::RecipeLockedBones:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"locked\" must be a list of bone ids");
        case MessageId::RecipeDabNeedsCenter:
            return RIGMESH_TRANSLATABLE("EngineMessage", "a dab needs \"center\" and \"radius\"");
        case MessageId::RecipeStepNeedsCenter:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the step needs \"center\" and \"radius\"");
        case MessageId::RecipeDabsOrCenter:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "the step needs either \"center\" and \"radius\" or \"dabs\"");
        case MessageId::RecipeDabsList:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "\"dabs\" must be a non-empty list of {\"center\", \"radius\"}");
        case MessageId::RecipeWholeNumber:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"%1\" must be a whole number from %2 to %3");
        case MessageId::RecipeStepNeeds:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the step needs \"%1\"");
        case MessageId::RecipeStrokeOrPoints:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the step needs either \"stroke\" (a sketch file) or \"points\", not both");
        case MessageId::RecipeTargetOrRotations:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the step needs either \"joint\" and \"target\" (an IK drag) or \"rotations\"");
        case MessageId::RecipeGoesWithRotations:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"%1\" goes with \"rotations\", not \"target\"");
        case MessageId::RecipeReach:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"reach\" must be \"limb\" or \"body\"");
        case MessageId::RecipeReachGoesWithTarget:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "\"reach\" goes with \"target\" (an IK drag), not \"rotations\"");
        case MessageId::RecipeInterpolation:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"interpolation\" must be \"constant\", \"linear\" or \"smooth\"");
        case MessageId::RecipePlayback:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"playback\" must be \"hold\", \"loop\" or \"ping_pong\"");
        case MessageId::RecipeTimes:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"times\" must be a list of seconds");
        case MessageId::RecipeKeys:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"keys\" must be a list of keys");
        case MessageId::RecipeKeyFields:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "each key needs \"time\" and \"rotations\"");
        case MessageId::RecipeWholeFrame:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"%1\" must be a whole frame");
        case MessageId::RecipeMergeMode:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"mode\" must be \"snap\", \"split\" or \"connect\"");
        case MessageId::RecipeReskin:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"reskin\" must be \"local\" or \"global\"");
        case MessageId::RecipePlaneOrStroke:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "the step needs either \"plane\" or \"stroke\" with \"view\"");
        case MessageId::RecipePlaneFields:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"plane\" needs \"point\" and \"normal\"");
        case MessageId::RecipeViewFields:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"view\" needs \"direction\" and \"up\"");
        case MessageId::RecipeCutStrokeTooShort:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the cut needs a stroke of two points or more");
        case MessageId::RecipeJoinStyle:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"style\" must be \"smooth\" or \"sharp\"");
        case MessageId::RecipeTwoNames:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"names\" must be two names");
        case MessageId::RecipePartsList:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "\"parts\" must be a non-empty list of parts, without \"part\"");
        case MessageId::RecipeUnknownCommand:
            return RIGMESH_TRANSLATABLE("EngineMessage", "unknown command \"%1\"");
        case MessageId::RecipeUnknownField:
            return RIGMESH_TRANSLATABLE("EngineMessage", "unknown field \"%1\"");
        case MessageId::RecipeNotARecipe:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "this is not a RigMesh recipe (it needs \"format\": \"%1\")");
        case MessageId::RecipeNoVersion:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the recipe has no valid \"version\"");
        case MessageId::RecipeVersionTooNew:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the recipe is of version %1; this RigMesh Studio reads recipes of version %2 and "
                "older");
        case MessageId::RecipeNoSteps:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the recipe has no list of \"steps\"");
        case MessageId::RecipeNotJson:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not valid JSON: %2");
        case MessageId::RecipeNumberOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has a number out of range: %2");
        case MessageId::RecipeCannotRead:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot read the recipe %1");
        case MessageId::RecipeCannotWriteFolder:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot write %1: the folder does not exist or is read-only");
        case MessageId::RecipeCannotWrite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot write %1");
        case MessageId::RecipeEdgeLength:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "\"edgeLength\" must be 0 (automatic) or a positive length");
        case MessageId::RecipePointsList:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "\"points\" must be a list of [x, y] points");
        case MessageId::RecipeRotationsObject:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"rotations\" must be an object {\"<joint id>\": [w, x, y, z], ...}");
        case MessageId::RecipeFieldNumberList:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be a list of %2 numbers");
        case MessageId::RecipeFieldQuaternionList:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 must be a list of 4 numbers [w, x, y, z]");
        case MessageId::RecipeFieldObject:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be an object");
        case MessageId::RecipeFieldUnknown:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has an unknown field \"%2\"");
        case MessageId::RecipeFieldNumber:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be a number");
        case MessageId::RecipeFieldFiniteNumber:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be a finite number");
        case MessageId::RecipeFieldTrueOrFalse:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be true or false");
        case MessageId::RecipeFieldText:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 must be text");
        case MessageId::RecipeFieldZeroQuaternion:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is a zero quaternion");
        case MessageId::RecipeFieldNotJointId:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not a joint id");
        case MessageId::RecipeFieldJointIdType:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 must be a joint id (a non-negative integer)");
        case MessageId::RecipeRotationsJointTwice:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"rotations\" names joint %1 twice");
        default:
            return nullptr;
    }
}

}  // namespace rigmesh
