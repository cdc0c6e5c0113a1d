// Engine messages by id (base/Message.h): the English text an Error shows is
// its template filled with its arguments, and the id and arguments travel
// with it so the studio can translate them.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>
#include <stdexcept>

#include "base/Error.h"
#include "base/Message.h"
#include "sketch/Sketch.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

TEST(EngineMessages, ErrorKeepsIdAndArgumentsBesideItsEnglishText) {
    const Error error(MessageId::PartHasNoBone, 7);
    EXPECT_EQ(error.message().id, MessageId::PartHasNoBone);
    EXPECT_EQ(error.message().args, std::vector<std::string>{"7"});
    EXPECT_STREQ(error.what(), "The part has no bone 7.");
}

TEST(EngineMessages, ErrorWithoutIdIsItsTextAlone) {
    const Error error(std::string("cannot export: a part is missing"));
    EXPECT_EQ(error.message().id, MessageId::None);
    EXPECT_TRUE(error.message().args.empty());
    EXPECT_STREQ(error.what(), "cannot export: a part is missing");
}

TEST(EngineMessages, NestedMessagesFillTheMarkersAfterTheArguments) {
    const Message stepFailed{MessageId::RecipeStepFailed,
                             {"3", "pose"},
                             {Message{MessageId::DataFieldMissing, {"\"rotations\""}}}};
    EXPECT_EQ(englishText(stepFailed), "step 3 (pose): missing \"rotations\"");
    // Nested twice: each level is filled in before the one around it.
    const Message twice{MessageId::RecipeStepFailed, {"1", "sketch"}, {stepFailed}};
    EXPECT_EQ(englishText(twice), "step 1 (sketch): step 3 (pose): missing \"rotations\"");
    EXPECT_STREQ(Error(stepFailed).what(), "step 3 (pose): missing \"rotations\"");
}

TEST(EngineMessages, AnyExceptionBecomesAMessageToNest) {
    const Error withId(MessageId::PartHasNoBone, 7);
    EXPECT_EQ(messageOf(withId), withId.message());
    // A library's own words, or an Error without an id, travel as they are.
    const Message library = messageOf(std::runtime_error("filesystem error: no such file"));
    EXPECT_EQ(library.id, MessageId::UntranslatedText);
    EXPECT_EQ(englishText(library), "filesystem error: no such file");
    EXPECT_EQ(englishText(messageOf(Error(std::string("plain words")))), "plain words");
}

TEST(EngineMessages, AFileThatIsNotJsonSaysWhyByIdInsideItsOwnMessage) {
    try {
        parseSketchJson("{\"strokes\": [", "cut.json");
        FAIL() << "half a JSON object is no sketch";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::SketchNotJson);
        EXPECT_EQ(error.message().args, std::vector<std::string>{"cut.json"});
        ASSERT_EQ(error.message().nested.size(), 1u);
        // A JSON text that stops early is a syntax error where it stops
        // (CBOR's early end is DataEndsEarly: TranslatedStudio's damaged document).
        EXPECT_EQ(error.message().nested[0].id, MessageId::DataMalformedAt);
        EXPECT_EQ(std::string(error.what()),
                  "Sketch \"cut.json\" is not valid JSON: it is malformed at byte 14");
    }
}

TEST(EngineMessages, FillingReplacesEachMarkerOnceInOnePass) {
    // An argument holding "%2" stays as it is; the markers may come in any order.
    EXPECT_EQ(fillMessage("%2 then %1", {"a%2", "b"}), "b then a%2");
    EXPECT_EQ(fillMessage("100% of %1", {"x"}), "100% of x");
    EXPECT_EQ(fillMessage("%1 and %3", {"x"}), "x and %3");  // a missing one stays visible
}

TEST(EngineMessages, EveryIdHasATemplateUsingMarkersFromOneUpwards) {
    std::set<std::string> templates;
    const std::regex marker("%([1-9])");
    for (int i = static_cast<int>(MessageId::None) + 1; i < static_cast<int>(MessageId::Count);
         ++i) {
        const std::string text = messageTemplate(static_cast<MessageId>(i));
        ASSERT_FALSE(text.empty()) << "message id " << i << " has no template";
        EXPECT_TRUE(templates.insert(text).second) << "two ids share the template: " << text;
        // %1 .. %k all used, none skipped, so each argument has its place.
        std::set<int> used;
        for (auto m = std::sregex_iterator(text.begin(), text.end(), marker);
             m != std::sregex_iterator(); ++m)
            used.insert(std::stoi((*m)[1]));
        if (!used.empty()) {
            EXPECT_EQ(*used.rbegin(), static_cast<int>(used.size())) << text;
        }
    }
}

TEST(EngineMessages, BadStrokesThrowErrorsWithIdsAndArguments) {
    try {
        cleanStroke({{0.0, 0.0}, {1.0, 0.0}});
        FAIL() << "two points are no silhouette";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::StrokeTooFewDistinctPoints);
        EXPECT_EQ(error.message().args, std::vector<std::string>{"2"});
    }
    // A figure eight crosses itself near its middle.
    std::vector<Vec2> eight;
    for (int i = 0; i < 200; ++i) {
        const double t = 2.0 * M_PI * i / 200.0;
        eight.emplace_back(std::sin(t), std::sin(t) * std::cos(t));
    }
    try {
        cleanStroke(eight);
        FAIL() << "a figure eight crosses itself";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::StrokeCrossesItselfNear);
        ASSERT_EQ(error.message().args.size(), 1u);
        EXPECT_EQ(error.what(), englishText(error.message()));
    }
}

}  // namespace
}  // namespace rigmesh
