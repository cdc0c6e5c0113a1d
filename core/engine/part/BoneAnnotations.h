// What a part says about its bones beyond the skeleton (part/Part.h): names
// from an imported file, locks for painting, and whether weights were painted
// by hand. Carried by every edit that makes a new skeleton (cut, merge, bone
// split and delete) the same way.
#pragma once

#include <map>

#include "part/Part.h"

namespace rigmesh {

// Puts `from`'s bone names and locks onto `to` for every bone that survives
// in `to`'s skeleton: bone b of `from` is bone renamed->at(b) of `to` (bones
// missing from `renamed` are dropped), or bone b itself without `renamed`.
// `to` counts as hand-painted if either part was. Annotations `to` already
// has are kept.
void carryBoneAnnotations(const Part& from, Part& to,
                          const std::map<BoneId, BoneId>* renamed = nullptr);

}  // namespace rigmesh
