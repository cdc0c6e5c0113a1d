// Seeded mutations of test inputs (no coverage feedback): byte flips,
// truncation, deleted and duplicated ranges, splices of another seed,
// numbers replaced by huge, tiny, negative, NaN or infinite ones, and deep
// nesting. Structured inputs (JSON text, CBOR) are also mutated as trees:
// numbers, lists and maps of the parsed value, re-encoded. The same seed
// gives the same sequence of inputs.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace rigmesh::fuzz {

// Bytes: binary or line-based formats (glb, fbx, ply, obj, off): byte and
// number mutations only.
enum class InputKind { JsonText, SvgText, Cbor, Bytes };

class Mutator {
  public:
    Mutator(InputKind kind, std::vector<std::string> seeds, std::uint64_t seed);

    // One to three mutations stacked on a seed chosen at random.
    std::string next();

  private:
    void mutateBytes(std::string& input);
    void mutateText(std::string& input);
    void mutateTree(std::string& input);
    void nest(std::string& input);
    std::size_t position(const std::string& input);
    std::string token();

    InputKind kind_;
    std::vector<std::string> seeds_;
    std::mt19937_64 random_;
};

}  // namespace rigmesh::fuzz
