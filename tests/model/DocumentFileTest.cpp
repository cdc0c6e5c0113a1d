// The native file: exact round trips, deterministic bytes, and clear
// rejection of corrupt, truncated, foreign and newer files.
#include <QFile>
#include <QTemporaryDir>
#include <limits>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "model/commands/MovePartCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/SetPartVisibleCommand.h"

namespace rigmesh::model::test {
namespace {

std::unique_ptr<Document> sampleDocument() {
    auto document = std::make_unique<Document>();
    const PartId a = addPart(*document, testStrokes()[0], QStringLiteral("Body \u00e9"));
    const PartId b = addPart(*document, testStrokes()[3], QStringLiteral("Y"));
    Placement p;
    p.translation = Vec3(0.1, -1.0 / 3.0, 2.0e-17);
    p.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    document->undoStack()->push(new MovePartCommand(*document, b, p));
    document->undoStack()->push(new SetPartVisibleCommand(*document, a, false));
    BuildOptions options;
    options.smoothing = false;
    document->undoStack()->push(RebuildPartCommand::create(*document, a, options).release());
    return document;
}

QString writeBytes(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(bytes);
    return path;
}

void expectSameParts(const Document& a, const Document& b) {
    ASSERT_EQ(a.partCount(), b.partCount());
    for (int i = 0; i < a.partCount(); ++i) {
        const PartNode& x = a.parts()[i];
        const PartNode& y = b.parts()[i];
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.visible, y.visible);
        EXPECT_EQ(x.placement, y.placement);  // bit-exact doubles
        EXPECT_EQ(x.stroke, y.stroke);
        EXPECT_EQ(x.options, y.options);
        EXPECT_EQ(x.part->mesh.vertices, y.part->mesh.vertices);
        EXPECT_EQ(x.part->mesh.faces, y.part->mesh.faces);
        EXPECT_EQ(x.part->mirror, y.part->mirror);
        EXPECT_EQ(x.part->weights.perVertex, y.part->weights.perVertex);
        EXPECT_EQ(x.part->knownClosestBones, y.part->knownClosestBones);
        EXPECT_EQ(x.part->outline, y.part->outline);
        ASSERT_EQ(x.part->origins.size(), y.part->origins.size());
        for (std::size_t v = 0; v < x.part->origins.size(); ++v) {
            EXPECT_EQ(x.part->origins[v].axisPosition, y.part->origins[v].axisPosition);
            EXPECT_EQ(x.part->origins[v].region, y.part->origins[v].region);
        }
        const Skeleton& s = x.part->skeleton;
        const Skeleton& t = y.part->skeleton;
        EXPECT_EQ(s.root(), t.root());
        ASSERT_EQ(s.jointCount(), t.jointCount());
        for (int j = 0; j < s.jointCount(); ++j) {
            EXPECT_EQ(s.joints()[j].id, t.joints()[j].id);
            EXPECT_EQ(s.joints()[j].position, t.joints()[j].position);
        }
        ASSERT_EQ(s.boneCount(), t.boneCount());
        for (int j = 0; j < s.boneCount(); ++j) {
            EXPECT_EQ(s.bones()[j].id, t.bones()[j].id);
            EXPECT_EQ(s.bones()[j].head, t.bones()[j].head);
            EXPECT_EQ(s.bones()[j].tail, t.bones()[j].tail);
        }
    }
}

TEST(DocumentFile, SaveLoadRoundTripIsExact) {
    QTemporaryDir dir;
    auto document = sampleDocument();
    const QString path = dir.filePath(QStringLiteral("scene.rigmesh"));
    DocumentFile::save(*document, path);
    EXPECT_FALSE(document->isModified());
    EXPECT_EQ(document->filePath(), path);

    auto loaded = DocumentFile::load(path);
    EXPECT_FALSE(loaded->isModified());
    EXPECT_EQ(loaded->filePath(), path);
    EXPECT_EQ(loaded->nextPartId(), document->nextPartId());
    expectSameParts(*document, *loaded);
    EXPECT_EQ(bytesOf(*loaded), bytesOf(*document));

    const QString again = dir.filePath(QStringLiteral("again.rigmesh"));
    DocumentFile::save(*loaded, again);
    QFile a(path), b(again);
    ASSERT_TRUE(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    EXPECT_EQ(a.readAll(), b.readAll());
}

TEST(DocumentFile, SavingTwiceGivesTheSameBytes) {
    auto document = sampleDocument();
    EXPECT_EQ(bytesOf(*document), bytesOf(*document));
    auto other = sampleDocument();  // built again from the same strokes
    EXPECT_EQ(bytesOf(*document), bytesOf(*other));
}

TEST(DocumentFile, EmptyDocumentRoundTrips) {
    Document document;
    const DocumentContents contents = DocumentFile::fromBytes(bytesOf(document));
    EXPECT_TRUE(contents.parts.empty());
    EXPECT_EQ(contents.nextPartId, 1u);
}

TEST(DocumentFile, LoadedDocumentKeepsAllocatingFreshIds) {
    auto document = sampleDocument();
    Document loaded(DocumentFile::fromBytes(bytesOf(*document)));
    const PartId id = addPart(loaded, testStrokes()[1]);
    for (const PartNode& node : document->parts())
        EXPECT_NE(node.id, id);
}

TEST(DocumentFile, TruncatedFilesAreRejected) {
    const QByteArray bytes = bytesOf(*sampleDocument());
    for (const qsizetype size : {qsizetype(1), qsizetype(3), qsizetype(4), qsizetype(40),
                                 bytes.size() / 2, bytes.size() - 1})
        expectRejected(bytes.left(size),
                       size < 3 ? "not a RigMesh Studio document" : "corrupt or truncated");
    expectRejected(QByteArray(), "empty");
}

TEST(DocumentFile, CorruptFilesAreRejected) {
    const QByteArray bytes = bytesOf(*sampleDocument());
    expectRejected(QByteArray("{\"format\": \"rigmesh-studio-document\"}"),
                   "not a RigMesh Studio document");
    expectRejected(bytes + QByteArray("x"), "corrupt or truncated");

    // Structurally valid CBOR with bad contents.
    using nlohmann::json;
    const json good = documentJson(bytes);
    json bad = good;
    bad["parts"][0]["part"]["mesh"]["faces"][0] = 1000000;
    expectRejected(documentBytes(bad), "face refers to a missing vertex");
    bad = good;
    bad["parts"][0]["part"]["mesh"].erase("vertices");
    expectRejected(documentBytes(bad), "missing \"vertices\"");
    bad = good;
    bad["parts"][1]["id"] = bad["parts"][0]["id"];
    expectRejected(documentBytes(bad), "same id");
    bad = good;
    bad["parts"][0]["name"] = 12;
    expectRejected(documentBytes(bad), R"("parts" "name" is not text)");
    bad = good;
    bad["parts"][0]["part"]["weights"]["byBoneId"][0] = json::array({99, 1.0});
    expectRejected(documentBytes(bad), "bone 99, which the skeleton does not have");
    bad = good;
    bad["parts"][0]["part"]["skeleton"]["root"] = 424242;
    expectRejected(documentBytes(bad), "root");
    bad = good;
    bad["format"] = "something-else";
    expectRejected(documentBytes(bad), "not a RigMesh Studio document");
    bad = good;
    bad["nextPartId"] = 1;
    expectRejected(documentBytes(bad), "next part id");
}

// The sample document as json, changed by `edit`, encoded back to a file.
template <typename Edit>
QByteArray editedSample(const Edit& edit) {
    using nlohmann::json;
    static const QByteArray bytes = bytesOf(*sampleDocument());
    json root = documentJson(bytes);
    edit(root);
    return documentBytes(root);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(DocumentFile, NonFiniteMeshVerticesAreRejected) {
    expectRejected(
        editedSample([](auto& root) { root["parts"][0]["part"]["mesh"]["vertices"][4] = kNaN; }),
        R"("mesh" "vertices" holds a value that is not finite)");
    expectRejected(editedSample([](auto& root) {
                       root["parts"][1]["part"]["mesh"]["vertices"][0] = -kInfinity;
                   }),
                   R"("mesh" "vertices" holds a value that is not finite)");
}

TEST(DocumentFile, NonFiniteJointPositionsAreRejected) {
    expectRejected(editedSample([](auto& root) {
                       root["parts"][1]["part"]["skeleton"]["joints"]["positions"][2] = kInfinity;
                   }),
                   R"("skeleton" "joints" "positions" holds a value that is not finite)");
}

TEST(DocumentFile, NonFiniteStrokeAndOutlineAreRejected) {
    expectRejected(editedSample([](auto& root) { root["parts"][0]["stroke"][3] = kNaN; }),
                   R"("stroke" holds a value that is not finite)");
    expectRejected(editedSample([](auto& root) { root["parts"][0]["part"]["outline"][0] = kNaN; }),
                   R"("part" "outline" holds a value that is not finite)");
}

TEST(DocumentFile, BadSkinWeightsAreRejected) {
    // Vertex 0's first weight: NaN, negative, or breaking the sum of 1.
    const auto firstWeight = [](double value) {
        return editedSample(
            [value](auto& root) { root["parts"][1]["part"]["weights"]["byBoneId"][0][1] = value; });
    };
    expectRejected(firstWeight(kNaN), R"("weights" "byBoneId" holds a value that is not finite)");
    expectRejected(firstWeight(-0.5), R"("weights" "byBoneId" holds a negative value)");
    expectRejected(firstWeight(7.0), "skin weights of vertex 0 sum to");
    expectRejected(editedSample([](auto& root) {
                       root["parts"][1]["part"]["weights"]["byBoneId"] = nlohmann::json::array();
                   }),
                   "needs skin weights for every vertex");
}

TEST(DocumentFile, NonFiniteOrNonUnitPlacementsAreRejected) {
    expectRejected(
        editedSample([](auto& root) { root["parts"][1]["placement"]["translation"][1] = kNaN; }),
        R"("placement" "translation" holds a value that is not finite)");
    expectRejected(
        editedSample([](auto& root) { root["parts"][1]["placement"]["rotation"][0] = kInfinity; }),
        R"("placement" "rotation" holds a value that is not finite)");
    expectRejected(editedSample([](auto& root) {
                       root["parts"][1]["placement"]["rotation"] = {2.0, 0.0, 0.0, 0.0};
                   }),
                   "placement rotation of part 2 is not a unit quaternion");
}

TEST(DocumentFile, NegativeOrNonFiniteEdgeLengthIsRejected) {
    const auto edgeLength = [](double value) {
        return editedSample(
            [value](auto& root) { root["parts"][0]["options"]["targetEdgeLength"] = value; });
    };
    expectRejected(edgeLength(-0.1), "must be 0 (automatic) or a positive length");
    expectRejected(edgeLength(kNaN),
                   R"("options" "targetEdgeLength" holds a value that is not finite)");
    // 0 (automatic) and a positive length load; how fine a length the
    // sketch allows is checked when the part is rebuilt (the engine's budget).
    EXPECT_NO_THROW(DocumentFile::fromBytes(edgeLength(0.0)));
    EXPECT_NO_THROW(DocumentFile::fromBytes(edgeLength(0.1)));
}

TEST(DocumentFile, SkeletonThatIsNotATreeIsRejected) {
    expectRejected(editedSample([](auto& root) {
                       auto& bones = root["parts"][1]["part"]["skeleton"]["bones"];
                       bones["tails"][0] = bones["heads"][0];  // a bone from a joint to itself
                   }),
                   "the skeleton is not a tree");
}

TEST(DocumentFile, ClipKeyTimesOutOfRangeAreRejected) {
    const auto clipWithKeysAt = [](double last, double framesPerSecond) {
        return editedSample([=](auto& root) {
            auto& clip = root["parts"][1]["clip"];
            const nlohmann::json pose = root["parts"][1]["pose"];
            clip["framesPerSecond"] = framesPerSecond;
            clip["keys"] = {{{"time", 0.0}, {"pose", pose}}, {{"time", last}, {"pose", pose}}};
        });
    };
    expectRejected(clipWithKeysAt(1e9, 24), "out of range");
    EXPECT_EQ(DocumentFile::fromBytes(clipWithKeysAt(10.0, 24)).parts[1].clip.keyCount(), 2);
}

// A part's invariants (Part::validate) and, for a surface made here, what
// merge and cut rely on: closed, manifold, consistently oriented.
TEST(DocumentFile, AFaceCornerMovedOntoAnotherVertexIsRejectedNamingThePart) {
    const auto moved = [](bool fromFile) {
        return editedSample([fromFile](auto& root) {
            auto& part = root["parts"][1]["part"];
            auto& faces = part["mesh"]["faces"];
            // Face 0's first corner onto a vertex of another face, not its own.
            for (std::size_t k = 3; k < faces.size(); ++k)
                if (faces[k] != faces[0] && faces[k] != faces[1] && faces[k] != faces[2]) {
                    faces[0] = faces[k];
                    break;
                }
            if (fromFile)
                part["surfaceFromFile"] = true;
        });
    };
    expectRejected(moved(false), "boundary edges");
    expectRejected(moved(false), "part 2 (\"Y\")");
    // An imported surface may be open: it loads (merge and cut refuse it).
    EXPECT_EQ(DocumentFile::fromBytes(moved(true)).parts.size(), 2u);
    // A face repeating a vertex breaks Part::validate for any part.
    expectRejected(editedSample([](auto& root) {
                       auto& part = root["parts"][1]["part"];
                       part["surfaceFromFile"] = true;
                       part["mesh"]["faces"][0] = part["mesh"]["faces"][1];
                   }),
                   "repeats a vertex");
}

// Documents written before Part::surfaceFromFile was stored: a merged or cut
// part (no outline) with a closed surface is held to the same checks as a
// sketch's; only an open one is taken for an import.
TEST(DocumentFile, AnOlderDocumentsClosedPartWithoutOutlineIsCheckedAsMadeHere) {
    const auto older = [](bool open) {
        return editedSample([open](auto& root) {
            auto& part = root["parts"][1]["part"];
            part.erase("surfaceFromFile");
            part["outline"] = nlohmann::json::array();
            if (open) {  // face 0 turned over: its edges are no longer shared properly
                auto& faces = part["mesh"]["faces"];
                std::swap(faces[1], faces[2]);
            }
        });
    };
    const DocumentContents closed = DocumentFile::fromBytes(older(false));
    ASSERT_EQ(closed.parts.size(), 2u);
    EXPECT_FALSE(closed.parts[1].part->surfaceFromFile);
    const DocumentContents flipped = DocumentFile::fromBytes(older(true));
    ASSERT_EQ(flipped.parts.size(), 2u);
    EXPECT_TRUE(flipped.parts[1].part->surfaceFromFile);
}

TEST(DocumentFile, ACorruptFileNamesNoLibraryInternals) {
    const QByteArray bytes = bytesOf(*sampleDocument());
    for (const QByteArray& bad : {bytes.left(bytes.size() / 3), bytes + QByteArray("x"),
                                  QByteArray("\xD9\xD9\xF7\xFF\x00", 5)}) {
        try {
            DocumentFile::fromBytes(bad);
            ADD_FAILURE() << "accepted";
        } catch (const DocumentFileError& e) {
            const std::string text = e.what();
            EXPECT_EQ(text.find("json.exception"), std::string::npos) << text;
            EXPECT_EQ(text.find("parse_error"), std::string::npos) << text;
            EXPECT_NE(text.find("byte"), std::string::npos) << "says where: " << text;
        }
    }
}

TEST(DocumentFile, DeeplyNestedListsAreRejectedWithoutRecursingIntoThem) {
    // 100000 nested one-element arrays: 100 kB that would overflow the stack.
    QByteArray bytes("\xD9\xD9\xF7", 3);
    bytes.append(QByteArray(100000, '\x81'));
    bytes.append('\x01');
    expectRejected(bytes, "nested more than 32 levels deep");
}

TEST(DocumentFile, NewerVersionIsRejectedWithAClearMessage) {
    using nlohmann::json;
    const QByteArray bytes = bytesOf(*sampleDocument());
    json root = documentJson(bytes);
    root["version"] = DocumentFile::kFormatVersion + 1;
    expectRejected(documentBytes(root), "newer RigMesh Studio (format version " +
                                            std::to_string(DocumentFile::kFormatVersion + 1) + ")");
}

TEST(DocumentFile, LoadFailureOpensNothingAndNamesTheFile) {
    QTemporaryDir dir;
    const QByteArray bytes = bytesOf(*sampleDocument());
    const QString path = writeBytes(dir, QStringLiteral("broken.rigmesh"), bytes.left(100));
    std::unique_ptr<Document> document;
    try {
        document = DocumentFile::load(path);
        ADD_FAILURE() << "loaded a truncated file";
    } catch (const DocumentFileError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.rigmesh"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(document);
    EXPECT_THROW(DocumentFile::load(dir.filePath(QStringLiteral("missing.rigmesh"))),
                 DocumentFileError);
}

TEST(DocumentFile, FailedSaveLeavesTheOldFileAndTheModifiedState) {
    QTemporaryDir dir;
    auto document = sampleDocument();
    EXPECT_THROW(
        DocumentFile::save(*document, dir.filePath(QStringLiteral("no/such/dir/x.rigmesh"))),
        DocumentFileError);
    EXPECT_TRUE(document->isModified());
    EXPECT_TRUE(document->filePath().isEmpty());
}

}  // namespace
}  // namespace rigmesh::model::test
