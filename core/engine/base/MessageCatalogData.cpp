// The English templates of the engine messages about saved data: what is
// wrong in a document, recipe or sketch file (base/JsonRead,
// part/PartJson), and a recipe step's failure (model/recipe/RecipeRunner).
// See MessageCatalog.cpp: RIGMESH_TRANSLATABLE marks each for lupdate, in
// the context "EngineMessage". A field is named by its path in the file
// ("skeleton" "joints" "ids"), which every language keeps as it is. An id not
// handled here is another file's.
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

namespace {

// Reading any JSON or CBOR value (base/JsonRead).
const char* valueTemplate(MessageId id) {
    switch (id) {
        case MessageId::UntranslatedText:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1");
        case MessageId::DataNotMap:
            return RIGMESH_TRANSLATABLE("EngineMessage", "expected a map holding %1");
        case MessageId::DataFieldMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage", "missing %1");
        case MessageId::DataNotList:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not a list");
        case MessageId::DataNotNumber:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not a number");
        case MessageId::DataNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 holds a value that is not finite");
        case MessageId::DataNotBoolean:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not true or false");
        case MessageId::DataNotText:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not text");
        case MessageId::DataWrongLength:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has the wrong length");
        case MessageId::DataNotInteger:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is not an integer");
        case MessageId::DataOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 is out of range");
        case MessageId::DataEndsEarly:
            return RIGMESH_TRANSLATABLE("EngineMessage", "it ends too early, at byte %1");
        case MessageId::DataMalformedAt:
            return RIGMESH_TRANSLATABLE("EngineMessage", "it is malformed at byte %1");
        case MessageId::DataNumberTooLarge:
            return RIGMESH_TRANSLATABLE("EngineMessage", "it holds a number too large to read");
        case MessageId::DataWrongType:
            return RIGMESH_TRANSLATABLE("EngineMessage", "a value has the wrong type");
        case MessageId::DataMalformed:
            return RIGMESH_TRANSLATABLE("EngineMessage", "it is malformed");
        default:
            return nullptr;
    }
}

// A part as documents store it (part/PartJson).
const char* partTemplate(MessageId id) {
    switch (id) {
        case MessageId::DataUnknownWeightNote:
            return RIGMESH_TRANSLATABLE("EngineMessage", "unknown weights warning %1");
        case MessageId::DataWeightNoteArguments:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "weights warning %1 has the wrong number of arguments");
        case MessageId::DataMissingBoneAtIndex:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 refers to a missing bone");
        case MessageId::DataMissingBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "%1 refers to bone %2, which the skeleton does not have");
        case MessageId::DataNotPerVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 does not have one entry per vertex");
        case MessageId::DataMalformedEntry:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 has a malformed entry");
        case MessageId::DataNegative:
            return RIGMESH_TRANSLATABLE("EngineMessage", "%1 holds a negative value");
        case MessageId::DataWeightSum:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the skin weights of vertex %1 sum to %2 instead of 1");
        case MessageId::DataJointCountsDiffer:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "joint ids and positions differ in number");
        case MessageId::DataJointIdRepeated:
            return RIGMESH_TRANSLATABLE("EngineMessage", "duplicate or invalid joint id");
        case MessageId::DataBoneCountsDiffer:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "bone ids, heads and tails differ in number");
        case MessageId::DataBoneIdRepeated:
            return RIGMESH_TRANSLATABLE("EngineMessage", "duplicate bone id");
        case MessageId::DataBoneMissingJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "a bone refers to a missing joint");
        case MessageId::DataRootNotJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the skeleton root is not one of its joints");
        case MessageId::DataAttachmentCountsDiffer:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "attached joints and their bones differ in number");
        case MessageId::DataAttachmentMissing:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "an attachment refers to a missing joint or bone, or twice to one joint");
        case MessageId::DataSkeletonNotTree:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the skeleton is not a tree: %1");
        case MessageId::DataFaceMissingVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage", "a face refers to a missing vertex");
        case MessageId::DataUnknownOriginKind:
            return RIGMESH_TRANSLATABLE("EngineMessage", "unknown vertex origin kind");
        case MessageId::DataMirrorMissingVertex:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the mirror map refers to a missing vertex");
        case MessageId::DataWeightsMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a rigged part needs skin weights for every vertex");
        case MessageId::DataBoneNameMalformed:
            return RIGMESH_TRANSLATABLE("EngineMessage", "a bone name is not [bone id, name]");
        case MessageId::DataBoneNameMissingBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a bone name refers to a missing bone, or twice to one");
        case MessageId::DataLockedBoneMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a locked bone refers to a missing bone, or twice to one");
        case MessageId::DataBoneFrameMalformed:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a bone frame is not [bone id, w, x, y, z]");
        case MessageId::DataBoneFrameInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "a bone frame is not a unit rotation of a bone, or names one twice");
        case MessageId::DataPartInvalid:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the part fails its own check: %1");
        default:
            return nullptr;
    }
}

// A recipe step that could not be applied (model/recipe/RecipeRunner).
const char* recipeStepTemplate(MessageId id) {
    switch (id) {
        case MessageId::RecipeStepFailed:
            return RIGMESH_TRANSLATABLE("EngineMessage", "step %1 (%2): %3");
        case MessageId::RecipeStepNotObject:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "a step must be an object {\"command\": ..., ...}");
        case MessageId::RecipeStepNoCommand:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the step has no \"command\"");
        case MessageId::RecipeStepCommandNotText:
            return RIGMESH_TRANSLATABLE("EngineMessage", "\"command\" must be text");
        default:
            return nullptr;
    }
}

}  // namespace

const char* dataMessageTemplate(MessageId id) {
    for (const auto areaTemplate : {&valueTemplate, &partTemplate, &recipeStepTemplate})
        if (const char* text = areaTemplate(id))
            return text;
    return nullptr;
}

}  // namespace rigmesh
