// Writing files so that a crash or a full disk never leaves a truncated file
// where the user expects a complete one.
//
// A StagedFile writes its bytes to a temporary file beside the target,
// checking every write, the flush, the sync to disk and the close; it takes
// the permissions of the file it will replace. commit() renames it over the
// target. Until then the target is untouched, and the temporary file is
// removed when the StagedFile goes away uncommitted (every error path).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rigmesh {

class StagedFile {
  public:
    // Throws Error (naming `target`) when the folder does not exist, the
    // target is a folder or read-only, or any write fails (disk full).
    StagedFile(const std::filesystem::path& target, std::string_view bytes);
    ~StagedFile();
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;
    StagedFile(StagedFile&& other) noexcept;
    StagedFile& operator=(StagedFile&&) = delete;

    // Renames the temporary file over the target. Throws Error on failure
    // (the temporary file is then removed).
    void commit();

    const std::filesystem::path& target() const { return target_; }

  private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;  // empty once committed or moved from
};

// StagedFile(path, bytes).commit(): `path` is either unchanged or complete.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Throws Error unless `target` can be replaced: its folder exists, and it is
// not a folder or a read-only file.
void checkReplaceable(const std::filesystem::path& target);

}  // namespace rigmesh
