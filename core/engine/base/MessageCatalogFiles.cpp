// The English templates of the engine messages about mesh files, sketch files
// and exports (see MessageCatalog.cpp: RIGMESH_TRANSLATABLE marks each for
// lupdate, in the context "EngineMessage"). An id not handled here is another
// file's.
#include "base/MessageCatalogAreas.h"

namespace rigmesh {

const char* fileMessageTemplate(MessageId id) {
    switch (id) {
        // Mesh files (mesh/MeshReader, mesh/PlyReader, mesh/MeshWriter, mesh/MeshChecks)
        case MessageId::MeshFileCannotOpen:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot open '%1': the file does not exist or is not readable.");
        case MessageId::MeshFileReadFailed:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': reading the file failed.");
        case MessageId::MeshFileTypeUnsupported:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Unsupported mesh file type '%1': use .obj, .off or .ply.");
        case MessageId::MeshLineVertexCoordinates:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': line %2: a vertex needs three coordinates.");
        case MessageId::MeshLineFaceCorners:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': line %2: a face needs at least three vertices.");
        case MessageId::ObjFaceVertexUndefined:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': line %2: face refers to vertex %3 but only %4 vertices are "
                "defined before it.");
        case MessageId::MeshLineNotANumber:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': line %2: '%3' is not a finite number.");
        case MessageId::MeshLineNotAnInteger:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': line %2: '%3' is not an integer.");
        case MessageId::MeshLineInvalidCount:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': line %2: invalid count '%3'.");
        case MessageId::OffEndsBeforeHeader:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file ends early, while expecting the OFF header.");
        case MessageId::OffEndsBeforeCounts:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file ends early, while expecting the vertex and face "
                "counts.");
        case MessageId::OffEndsBeforeVertex:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file ends early, while expecting vertex %2 of %3.");
        case MessageId::OffEndsBeforeFace:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file ends early, while expecting face %2 of %3.");
        case MessageId::OffNoHeader:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': the file does not start with 'OFF'.");
        case MessageId::OffNoCounts:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': line %2: expected the vertex and face counts.");
        case MessageId::OffFaceCornerCount:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': line %2: a face needs a corner count of at least 3 and that "
                "many vertex indices.");
        case MessageId::OffFaceVertexOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': line %2: face refers to vertex %3 but there are %4 vertices.");
        case MessageId::PlyNoMagic:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': the file does not start with 'ply'.");
        case MessageId::PlyNoEndHeader:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': the header has no 'end_header' line.");
        case MessageId::PlyNoFormat:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': the header has no 'format' line.");
        case MessageId::PlyHeaderUnknownType:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': header line %2: unknown property type '%3'.");
        case MessageId::PlyHeaderUnknownFormat:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': header line %2: unknown format '%3'.");
        case MessageId::PlyHeaderNotAnInteger:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': header line %2: '%3' is not an integer.");
        case MessageId::PlyHeaderInvalidCount:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': header line %2: invalid element count '%3'.");
        case MessageId::PlyHeaderListCountType:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': header line %2: a list count must have an integer type.");
        case MessageId::PlyHeaderMalformedProperty:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': header line %2: malformed property line.");
        case MessageId::PlyHeaderUnexpected:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': header line %2: unexpected '%3'.");
        case MessageId::PlyTruncatedIn:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file is truncated: it ends in %2 %3 of %4.");
        case MessageId::PlyNotANumber:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': %2 %3 of %4: '%5' is not a finite number.");
        case MessageId::PlyListLengthOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': %2 %3 of %4: list length is %5, outside [0, %6).");
        case MessageId::PlyVertexIndexOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': %2 %3 of %4: vertex index is %5, outside [0, %6).");
        case MessageId::PlyFaceCorners:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': %2 %3 of %4: a face needs at least three vertices.");
        case MessageId::PlyCoordinateNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': %2 %3 of %4: a coordinate is not finite.");
        case MessageId::PlyNoXyz:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the vertex element lacks an x, y or z property.");
        case MessageId::PlyTwoVertexElements:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Cannot read '%1': the file has more than one vertex element.");
        case MessageId::PlyNoVertexIndices:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the face element lacks a 'vertex_indices' list.");
        case MessageId::PlyElementTooLarge:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': the file is truncated: element '%2' declares %3 entries that "
                "do not fit.");
        case MessageId::PlyNoVertexElement:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read '%1': the file has no vertex element.");
        case MessageId::PlyFaceVertexOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read '%1': face %2 refers to vertex %3 but there are %4 vertices.");
        case MessageId::MeshWriteVertexNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot write the mesh: vertex %1 is not a finite point.");
        case MessageId::MeshWriteFaceMissingVertex:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot write the mesh: face %1 refers to vertex %2 but there are only %3 "
                "vertices.");
        case MessageId::MeshVertexNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "The mesh has a vertex with a non-finite coordinate.");
        case MessageId::MeshFaceVertexMissing:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Face %1 refers to vertex %2 but the mesh has %3 vertices.");

        // Sketch files (sketch/Sketch, sketch/SvgSketch)
        case MessageId::SketchCoordinateNotNumber:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Sketch \"%1\": point %2 has %3 as its %4 coordinate; every coordinate must be a "
                "number.");
        case MessageId::SketchNotJson:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Sketch \"%1\" is not valid JSON: %2");
        case MessageId::SketchNumberOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\" has a number out of range: %2");
        case MessageId::SketchNotObject:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Sketch \"%1\" must be a JSON object with a \"points\" array of [x, y] pairs.");
        case MessageId::SketchNoPoints:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\" has no \"points\" array of [x, y] pairs.");
        case MessageId::SketchPointNotPair:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Sketch \"%1\": point %2 is not an [x, y] pair of numbers.");
        case MessageId::SketchFileTypeUnknown:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read sketch \"%1\": unknown file type \"%2\"; use a .json or .svg file.");
        case MessageId::SketchFileUnreadable:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Cannot read sketch file \"%1\": it does not exist or is not readable.");
        case MessageId::SketchFileReadFailed:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Cannot read sketch file \"%1\": reading it failed.");
        case MessageId::SketchNotSvg:
            return RIGMESH_TRANSLATABLE("EngineMessage", "Sketch \"%1\" is not valid SVG: %2");
        case MessageId::SketchNoSvgRoot:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "Sketch \"%1\" is not an SVG document (no <svg> root element).");
        case MessageId::SvgExpectedLetter:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: expected a letter in \"%4\"");
        case MessageId::SvgExpectedName:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: expected a name in \"%4\"");
        case MessageId::SvgExpectedNumber:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: expected a number in \"%4\"");
        case MessageId::SvgNumberOutOfRange:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: number out of range in \"%4\"");
        case MessageId::SvgExpectedArcFlag:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: expected an arc flag (0 or 1) in \"%4\"");
        case MessageId::SvgPathWithoutMoveto:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Sketch \"%1\": the SVG attribute \"%2\" is malformed at character %3: path data "
                "must start with a moveto command (M or m) in \"%4\"");
        case MessageId::SvgUnknownPathCommand:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: unknown command '%5' in \"%4\"");
        case MessageId::SvgOddCoordinateCount:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: odd number of coordinates in \"%4\"");
        case MessageId::SvgUnknownTransform:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Sketch \"%1\": the SVG attribute \"%2\" is malformed at character %3: unknown "
                "transform '%5' with %6 arguments in \"%4\"");
        case MessageId::SvgTransformWithoutOpening:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: expected '(' after '%5' in \"%4\"");
        case MessageId::SvgTransformWithoutClosing:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "Sketch \"%1\": the SVG attribute \"%2\" is malformed at "
                                        "character %3: missing ')' after '%5' in \"%4\"");
        case MessageId::SketchSvgNoStroke:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "Sketch \"%1\" contains no path, polyline or polygon to use as the stroke.");

        // Exports (io/)
        case MessageId::ExportGltfInvalidJson:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: the glTF exporter wrote invalid JSON");
        case MessageId::ExportGltfUnknownComponentType:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export: the glTF exporter wrote an unknown component type");
        case MessageId::ExportGltfAccessorOutside:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: a glTF accessor lies outside its buffer");
        case MessageId::ExportGltfBufferViewOutside:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export: the glTF exporter wrote a buffer view out of range");
        case MessageId::ExportGltfNoBuffer:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: the glTF exporter wrote no buffer");
        case MessageId::ExportColladaInvalidXml:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: the COLLADA exporter wrote invalid XML");
        case MessageId::ExportAnimationOfNothing:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot export an animation of nothing");
        case MessageId::ExportAnimationWithoutKeys:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot export an animation without keys");
        case MessageId::ExportAnimationNoNode:
            return RIGMESH_TRANSLATABLE("EngineMessage", "cannot export the animation: no node %1");
        case MessageId::ExportUnitScaleNotPositive:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: the unit scale must be positive");
        case MessageId::ExportUnknownFormat:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export %1: unknown format '%2'; use .glb, .gltf, .fbx, .dae or .obj");
        case MessageId::ExportRigNoSkeleton:
            return RIGMESH_TRANSLATABLE("EngineMessage", "part '%1' has no skeleton to export");
        case MessageId::RigJsonVertexNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot write the rig: vertex %1 is not at a finite position");
        case MessageId::RigJsonJointNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot write the rig: joint %1 is not at a finite position");
        case MessageId::RigJsonWeightNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot write the rig: a weight of vertex %1 is not finite");
        case MessageId::FbxRepairNotBinary:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot repair the FBX file: not a binary FBX file");
        case MessageId::FbxRepairNoRecords:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot repair the FBX file: no node records");
        case MessageId::FbxRepairRecordPastEnd:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot repair the FBX file: a record runs past the end of the file");
        case MessageId::FbxRepairNestedOutOfRange:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot repair the FBX file: a nested record is out of range");
        case MessageId::ExportVertexNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot export: vertex %1 of mesh '%2' is not a finite number");
        case MessageId::ExportNormalNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export: the normal of vertex %1 of mesh '%2' is not a finite number");
        case MessageId::ExportBindMatrixNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export: the bind matrix of bone '%1' is not a finite number");
        case MessageId::ExportBoneWeightNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot export: a weight of bone '%1' is not a finite number");
        case MessageId::ExportNodeTransformNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage",
                "cannot export: the transform of node '%1' is not a finite number");
        case MessageId::ExportKeyNotFinite:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot export: a key of '%1' is not a finite number");
        case MessageId::ExportDurationNotFinite:
            return RIGMESH_TRANSLATABLE(
                "EngineMessage", "cannot export: the animation's duration is not a finite number");
        case MessageId::ExportGltfNoBin:
            return RIGMESH_TRANSLATABLE("EngineMessage",
                                        "cannot write %1: the glTF exporter wrote no .bin");
        default:
            return nullptr;
    }
}

}  // namespace rigmesh
