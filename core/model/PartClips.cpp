#include "model/PartClips.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <set>

#include "base/Error.h"

namespace rigmesh::model {

std::string clipName(const rigmesh::Clip& clip) {
    return clip.name.empty() ? std::string(kDefaultClipName) : clip.name;
}

std::vector<const rigmesh::Clip*> clipsOf(const PartNode& node) {
    std::vector<const rigmesh::Clip*> out{&node.clip};
    for (const rigmesh::Clip& clip : node.otherClips)
        out.push_back(&clip);
    std::stable_sort(out.begin(), out.end(), [](const rigmesh::Clip* a, const rigmesh::Clip* b) {
        return clipName(*a) < clipName(*b);
    });
    return out;
}

const rigmesh::Clip* findClip(const PartNode& node, const std::string& name) {
    for (const rigmesh::Clip* clip : clipsOf(node))
        if (clipName(*clip) == name)
            return clip;
    return nullptr;
}

void checkClipName(const std::string& name) {
    if (name.empty() || name.size() > kMaxClipNameLength)
        throw Error(MessageId::ClipNameLength, kMaxClipNameLength);
    if (name.front() == ' ' || name.back() == ' ')
        throw Error(MessageId::ClipNameSpaces);
    if (std::any_of(name.begin(), name.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
        throw Error(MessageId::ClipNameControlCharacters);
}

void checkClipNamesUnique(const rigmesh::Clip& active, const std::vector<rigmesh::Clip>& others) {
    std::set<std::string> names{clipName(active)};
    for (const rigmesh::Clip& clip : others)
        if (!names.insert(clipName(clip)).second)
            throw Error(MessageId::ClipNameTwice, clipName(clip));
}

namespace {

// `text` cut to at most `bytes` bytes without splitting a UTF-8 character.
std::string utf8Prefix(const std::string& text, std::size_t bytes) {
    if (text.size() <= bytes)
        return text;
    std::size_t end = bytes;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
        --end;
    return text.substr(0, end);
}

std::string trimmed(std::string text) {
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    const std::size_t first = text.find_first_not_of(' ');
    return first == std::string::npos ? std::string() : text.substr(first);
}

}  // namespace

std::string usableClipName(const std::string& wanted, const std::set<std::string>& taken) {
    std::string name = wanted;
    for (char& c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = ' ';
    name = trimmed(utf8Prefix(trimmed(name), kMaxClipNameLength));
    if (name.empty())
        name = kDefaultClipName;
    if (!taken.contains(name))
        return name;
    for (int n = 1;; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        const std::string candidate =
            trimmed(utf8Prefix(name, kMaxClipNameLength - std::strlen(suffix))) + suffix;
        if (!taken.contains(candidate))
            return candidate;
    }
}

std::vector<rigmesh::Clip> sortedByName(std::vector<rigmesh::Clip> others) {
    std::stable_sort(
        others.begin(), others.end(),
        [](const rigmesh::Clip& a, const rigmesh::Clip& b) { return clipName(a) < clipName(b); });
    return others;
}

}  // namespace rigmesh::model
