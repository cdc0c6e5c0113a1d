// The English template of every engine message. Each text is wrapped in
// RIGMESH_TRANSLATABLE, which lupdate reads as QT_TRANSLATE_NOOP (see
// translations/CMakeLists.txt), so the studio's .ts files list them under
// the context "EngineMessage". This file holds the messages of drawing,
// building, merging, cutting, posing, painting, writing and importing;
// the files named in base/MessageCatalogAreas.h hold the others.
// MessageTest's EveryIdHasATemplateUsingMarkersFromOneUpwards fails for an
// id that no file has a template for.
#include "base/Message.h"

#include "base/MessageCatalogAreas.h"
#include "base/MessageText.h"

#include <sstream>

namespace rigmesh {

const char* messageTemplate(MessageId id) {
    switch (id) {
        case MessageId::None:
        case MessageId::Count:
            return "";

        case MessageId::StrokeNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Point %1 of the stroke (counting from 0) is %2, which is not a finite number: "
                "the sketch data is corrupt. Redraw the stroke.");
        case MessageId::StrokeOneDistinctPoint:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke has only 1 distinct point; a silhouette needs at least 3 points that "
                "enclose an area. Draw a closed outline.");
        case MessageId::StrokeTooFewDistinctPoints:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke has only %1 distinct points; a silhouette needs at least 3 points "
                "that enclose an area. Draw a closed outline.");
        case MessageId::StrokeRepeatsPositions:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke has %1 points but only %2 distinct positions; the other %3 repeat "
                "them, which is too little to describe a silhouette. Draw the outline as one "
                "continuous stroke.");
        case MessageId::StrokeTooLong:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke is too long for its size: at the requested spacing its outline would "
                "need more than %1 points. Draw a simpler outline or use a larger spacing.");
        case MessageId::StrokeOnALine:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "All points of the stroke lie on (nearly) one straight line, so it encloses no "
                "area. Draw a closed silhouette.");
        case MessageId::StrokeCrossesItselfNear:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke crosses itself near %1: draw a silhouette that does not cross "
                "itself.");
        case MessageId::StrokeNoWidth:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke encloses almost no area (it runs back along itself). Draw a "
                "silhouette with some width.");
        case MessageId::StrokeTooLarge:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The stroke's coordinates are too large to process; scale the sketch down.");
        case MessageId::OutlineTouchesItself:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the outline touches itself at (%1, %2)");
        case MessageId::OutlineCrossesItself:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the outline crosses itself: draw a silhouette that does not cross itself");
        case MessageId::OutlineTooFewPoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "an outline needs at least three points");
        case MessageId::OutlineRepeatedPoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the outline has repeated points");
        case MessageId::OutlineNoArea:
            return RIGMESH_TRANSLATABLE("EngineMessage", "the outline encloses no area");
        case MessageId::OutlineTooSimple:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the outline is too simple to have an axis: draw a larger, rounder shape");

        case MessageId::SketchSizeOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "the sketch is %1 across; sizes from %2 to %3 are supported");
        case MessageId::SketchTooFarFromOrigin:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the sketch lies too far from the origin for its size: near %1 doubles are %2 "
                "apart, more than a millionth of its edges (%3); move it within %4 of the "
                "origin");
        case MessageId::EdgeLengthTooSmall:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the edge length %1 is too small for this sketch: it would give about %2 "
                "vertices, more than the %3 allowed; use 0 (automatic: %4) or an edge length of "
                "at least %5");
        case MessageId::SurfaceNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the surface has a vertex with a non-finite coordinate; the sketch's numbers are "
                "beyond what double precision can build");
        case MessageId::SurfaceDegenerateFaces:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the surface has %1 degenerate faces; double precision cannot build this sketch "
                "at its position and size");
        case MessageId::EdgeLengthNotPositive:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "the target edge length must be 0 (automatic) or a positive length");
        case MessageId::SurfaceSmoothingNotFactored:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "least-squares smoothing failed: the surface system could not be factored");
        case MessageId::SurfaceSmoothingNoSolution:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "least-squares smoothing failed: the surface system has no finite solution");
        case MessageId::SurfaceSelfIntersecting:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The surface would intersect itself (%1 crossing face pairs) near (%2, "
                "%3): the outline is too thin or turns too sharply there. Widen it there "
                "or use a smaller edge length.");
        case MessageId::PartHasNoSketch:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "\"%1\" cannot be rebuilt: it was not drawn as one sketch (it comes from a "
                "merge, a cut, a bone edit or an import), so there is no stroke to build "
                "it from.");

        case MessageId::MergeNeedsRiggedParts:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Only rigged parts can be merged; rig the imported mesh first.");
        case MessageId::MergeInvalidResult:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The merge gave an invalid part (%1); nothing was changed.");
        case MessageId::MergeNoDraggedJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The dragged part has no joint %1.");
        case MessageId::MergeNoTargetJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The target part has no joint %1.");
        case MessageId::MergeNoTargetBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The target part has no bone %1.");
        case MessageId::MergeJointsCoincide:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The two joints to connect are at the same place; snap them instead.");
        case MessageId::MergeSelfIntersecting:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "One of the surfaces intersects itself, so the parts cannot be merged. Rebuild "
                "it with a larger edge length or smoothing, then merge again.");
        case MessageId::MergeNotManifold:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The merged surface would not be a manifold (the parts touch at a point or along "
                "a line). Move the dragged part so that it overlaps the other one, then merge "
                "again.");
        case MessageId::MergePartsApart:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The parts do not touch. Drag one part so that it overlaps the other, then "
                "merge.");
        case MessageId::MergePartInside:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "One part lies entirely inside the other, so merging would only delete it. Drag "
                "it so that it sticks out of the other part, then merge.");
        case MessageId::LocalWeightsUnsolved:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The local skin weights could not be solved; use the global re-computation.");
        case MessageId::MergeTargetNotSolid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The target part cannot be merged: %1 Merging needs closed, consistently "
                "oriented surfaces.");
        case MessageId::MergeDraggedNotSolid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The dragged part cannot be merged: %1 Merging needs closed, consistently "
                "oriented surfaces.");
        case MessageId::MergeTargetIntersectsItself:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The target part's surface intersects itself (%1 crossing face pairs), so "
                "the parts cannot be merged. Rebuild it with a larger edge length or "
                "smoothing first.");
        case MessageId::MergeDraggedIntersectsItself:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The dragged part's surface intersects itself (%1 crossing face pairs), "
                "so the parts cannot be merged. Rebuild it with a larger edge length or "
                "smoothing first.");
        case MessageId::MergeJointsTooClose:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The joints to connect are %1 apart, less than the shortest bone allowed "
                "(%2); snap them instead.");

        case MessageId::CutNeedsRiggedPart:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Only rigged parts can be cut; rig the imported mesh first.");
        case MessageId::CutNeedsPlane:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The cut needs a plane: a finite point and a non-zero normal.");
        case MessageId::CutStrokeNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The cut's stroke has a point that is not a finite number.");
        case MessageId::CutMissesPart:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut does not cross the part. Draw it across the part, from one side of its "
                "outline to the other.");
        case MessageId::CutCrossesTwice:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut crosses the part more than once (it would make %1 pieces). Cut where it "
                "crosses only once, or cut again.");
        case MessageId::CutPiecesOnOneSide:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut leaves two pieces on the same side of its plane; cut elsewhere.");
        case MessageId::CutPieceWithoutBone:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut leaves a piece without a bone. Cut across a bone, nearer the middle of "
                "the part.");
        case MessageId::CutPieceNotOneTree:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut leaves a piece whose skeleton is not one tree; cut elsewhere.");
        case MessageId::CutPatchWeightsUnsolved:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The patch's skin weights could not be solved; cut elsewhere.");
        case MessageId::CutInvalidPiece:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The cut gave an invalid piece (%1); nothing was changed.");
        case MessageId::CutStrokeTooShort:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A cut needs a stroke of two points or more and a view direction.");
        case MessageId::CutStrokeClosed:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The cut's stroke must not start and end at the same point.");
        case MessageId::BoneEditInvalidResult:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "The bone edit gave an invalid part (%1); nothing was changed.");
        case MessageId::PartHasNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no skeleton.");
        case MessageId::PartHasNoBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no bone %1.");
        case MessageId::SplitTooCloseToJoint:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "That is too close to a joint to split the bone; pick a point nearer its "
                "middle.");
        case MessageId::SplitBoneLeadsNothing:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "No part of the surface is led by that bone where it would be split.");
        case MessageId::DeleteOnlyBone:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A part keeps at least one bone; this is its only one.");
        case MessageId::BoneNotConnected:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Bone %1 is not connected to its parent; connect it first (Edit > Connect Bone).");
        case MessageId::ConnectBoneAlreadyConnected:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Bone %1 is already connected to its parent.");
        case MessageId::ConnectBoneHasNoParent:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Bone %1 starts at the skeleton's root: it has no parent to connect to.");
        case MessageId::CutPartNotSolid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The part cannot be cut: %1 Cutting needs a closed, consistently oriented "
                "surface.");
        case MessageId::CutPieceBoneTooShort:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The cut would leave a piece without a bone: its only one would be %1 long, "
                "shorter than the shortest bone allowed (%2). Cut farther from the joint.");
        case MessageId::SplitBoneTooShort:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Splitting there would leave a bone %1 long, shorter than the shortest "
                "bone allowed (%2); split nearer the bone's middle.");
        case MessageId::DeleteLeavesShortBone:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Deleting the bone would leave bone %1 only %2 long, shorter than the "
                "shortest bone allowed (%3); delete a neighbouring bone instead.");

        case MessageId::IkTargetNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The IK target is not a finite point.");
        case MessageId::PoseNeedsJoints:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Cannot pose a skeleton without joints.");
        case MessageId::PoseNeedsRoot:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot pose a skeleton without a valid root joint.");
        case MessageId::SkeletonHasNoJoint:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The skeleton has no joint %1.");
        case MessageId::PoseRotationInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "The pose gives joint %1 a rotation that is not a finite, non-zero quaternion.");
        case MessageId::PoseTranslationNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The pose's root translation is not finite.");
        case MessageId::KeyAlreadyAt:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is already a key at exactly %1 s.");
        case MessageId::NoKeyExactlyAt:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no key at exactly %1 s.");
        case MessageId::NoKeyAt:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no key at %1 s.");
        case MessageId::NoKeyToMove:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no key at %1 s to move.");
        case MessageId::NoKeyToDelete:
            return RIGMESH_TRANSLATABLE("EngineMessage", "There is no key at %1 s to delete.");
        case MessageId::ClipHasNoKeys:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The clip has no keys.");
        case MessageId::ClipPlayedWithoutKeys:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Cannot play a clip without keys.");
        case MessageId::KeyPoseInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A key's pose must have finite, non-zero rotations and a finite translation.");
        case MessageId::KeyTimeNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A key time must be a finite number of seconds.");
        case MessageId::KeyTimeNegative:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "A key at %1 s is out of range: keys lie at 0 s or later.");
        case MessageId::KeyTimeTooLate:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "A key at %1 s is out of range: keys lie from 0 s to %2 s.");
        case MessageId::ClipFrameRateInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A clip's frame rate must be a positive number of frames per second.");

        case MessageId::PaintNoSuchBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no bone %1 to paint.");
        case MessageId::PaintBoneLocked:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Bone %1 is locked; unlock it to paint it.");
        case MessageId::PaintLockedNoSuchBone:
            return RIGMESH_TRANSLATABLE("EngineMessage", "The part has no bone %1 to lock.");
        case MessageId::PaintBrushInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "A brush needs a finite centre, a positive radius, and a strength and value "
                "between 0 and 1.");
        case MessageId::PaintViewDirectionInvalid:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Front faces only needs a finite, non-zero view direction.");
        case MessageId::PaintMirrorAsymmetric:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "This part has no left-right mirror plane (its two sides differ by more than 2% "
                "of its size), so X-mirror cannot paint it.");
        case MessageId::CleanThresholdOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The clean threshold must be at least 0 and below 1.");
        case MessageId::LimitNeedsOneInfluence:
            return RIGMESH_TRANSLATABLE("EngineMessage", "A vertex needs at least one influence.");
        case MessageId::SmoothAllOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Smooth All needs a factor from 0 to 1 and 1 to 100 passes.");

        case MessageId::CannotWriteFile:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot write %1: %2");
        case MessageId::WriteFolderMissing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot write %1: the folder %2 does not exist");
        case MessageId::WriteTargetIsFolder:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot write %1: it is a folder");
        case MessageId::WriteReadOnly:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot write %1: the file is read-only");
        case MessageId::WriteCannotCreate:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot write %1: cannot create a file in %2: %3");
        case MessageId::WriteDiskFull:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot write %1: %2 (is the disk full?)");
        case MessageId::WritePermissionsLost:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot write %1: cannot keep its permissions: %2");
        case MessageId::ExportNoPart:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot export: there is no part");
        case MessageId::ExportPartWithoutSurface:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export part '%1': it has no surface");
        case MessageId::ExportWeightsMismatch:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export part '%1': its skin weights do not match its surface");
        case MessageId::ExportKeysTooClose:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export the clip: the times %1 s and %2 s are too close for 32-bit "
                "precision this far from 0 s; move the keys nearer to 0 s or further apart");
        case MessageId::SubdivisionLevelsOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "subdivision levels must be from 0 to 4, not %1");
        case MessageId::SubdivisionTooManyVertices:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "subdividing '%1' %2 times would give over %3 vertices; use fewer levels");
        case MessageId::DecimationTooFewFaces:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "decimating needs a target of at least 4 faces, not %1");
        case MessageId::DecimationNotManifold:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "the surface is not manifold, so it cannot be decimated");

        case MessageId::ImportNoSuchFile:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot import \"%1\": there is no such file.");
        case MessageId::ImportNotAFile:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Cannot import \"%1\": it is not a file.");
        case MessageId::ImportReaderMissing:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": the program that reads imports (rigmesh) is not "
                "installed.");
        case MessageId::ImportReaderNotStarted:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": the import reader could not be started (%2).");
        case MessageId::ImportTimedOut:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": reading it took longer than %2 s, so it was stopped "
                "(the file is probably broken).");
        case MessageId::ImportReaderCrashed:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": the importer crashed on it (%2); the file is "
                "probably broken.");
        case MessageId::ImportOutOfMemory:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": reading it needed more than %2 of memory, so it was "
                "stopped.");
        case MessageId::ImportReaderFailed:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot import \"%1\": the importer failed (exit status %2).");
        case MessageId::ImportBadData:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot import \"%1\": the importer returned bad data (%2).");
        case MessageId::ImportPartUnusable:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot import \"%1\": its part \"%2\" is not usable: %3");
        case MessageId::ImportUnreadable:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Cannot import \"%1\": %2");
        case MessageId::ImportUnknownFormat:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot import \"%1\": it is damaged or not in a format the importer knows.");
        case MessageId::ImportIncomplete:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot import \"%1\": the file is incomplete.");
        case MessageId::ImportNoTriangleMesh:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot import \"%1\": it holds no triangle mesh.");
        default:
            break;  // an id of another catalogue file
    }
    for (const auto areaTemplate :
         {&editingMessageTemplate, &fileMessageTemplate, &recipeMessageTemplate,
          &autoRigMessageTemplate, &dataMessageTemplate, &validationMessageTemplate})
        if (const char* text = areaTemplate(id))
            return text;
    return "";
}

std::string fillMessage(std::string_view text, const std::vector<std::string>& args) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        const std::size_t index = static_cast<std::size_t>(next - '1');
        if (text[i] == '%' && next >= '1' && next <= '9' && index < args.size()) {
            out += args[index];
            ++i;
        } else {
            out += text[i];
        }
    }
    return messageText(out);
}

std::string englishText(const Message& message) {
    std::vector<std::string> args = message.args;
    for (const Message& nested : message.nested)
        args.push_back(englishText(nested));
    return fillMessage(messageTemplate(message.id), args);
}

std::string englishText(const std::vector<Message>& messages) {
    std::string text;
    for (const Message& message : messages)
        text += (text.empty() ? "" : " ") + englishText(message);
    return text;
}

std::ostream& operator<<(std::ostream& out, const Message& message) {
    return out << englishText(message);
}

std::string shortNumber(double value) {
    std::ostringstream text;
    text.precision(3);
    text << value;
    return text.str();
}

}  // namespace rigmesh
