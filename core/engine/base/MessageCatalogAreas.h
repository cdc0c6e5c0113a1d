// The engine message catalogue is split by area, one file each; messageTemplate
// (MessageCatalog.cpp) asks them in turn. Each returns nullptr for an id that
// is not its own. Internal to the catalogue.
#pragma once

#include "base/Message.h"

// lupdate reads RIGMESH_TRANSLATABLE as QT_TRANSLATE_NOOP (translations/CMakeLists.txt).
#define RIGMESH_TRANSLATABLE(context, text) text

namespace rigmesh {

// MessageCatalogEditing.cpp: documents, commands, the timeline, clips,
// skeletons, skin weights and surfaces.
const char* editingMessageTemplate(MessageId id);
// MessageCatalogFiles.cpp: mesh files, sketch files and exports.
const char* fileMessageTemplate(MessageId id);
// MessageCatalogRecipes.cpp: recipes.
const char* recipeMessageTemplate(MessageId id);
// MessageCatalogAutoRig.cpp: rigging an imported mesh.
const char* autoRigMessageTemplate(MessageId id);
// MessageCatalogData.cpp: what is wrong in saved data (documents, recipes,
// sketches) and a recipe step's failure.
const char* dataMessageTemplate(MessageId id);
// MessageCatalogValidation.cpp: what keeps a part or a skeleton from being
// valid (Part::validate, Skeleton::validate).
const char* validationMessageTemplate(MessageId id);

}  // namespace rigmesh
