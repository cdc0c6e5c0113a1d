// The timeline's key edits as document operations, each one undo
// step (a macro when it touches several keys or parts): insert keys at the
// current frame, delete selected keys, copy them and paste them at the
// current frame. The dock calls these; they need no display.
#pragma once

#include <map>
#include <set>

#include "model/Document.h"

namespace rigmesh::model {

// Exact key times, per part (the timeline's key selection).
using KeySelection = std::map<PartId, std::set<double>>;

// Copied keys: their poses at times relative to the earliest copied key.
struct KeyClipboard {
    std::map<PartId, std::map<double, rigmesh::Pose>> keys;
    bool empty() const { return keys.empty(); }
};

// Keys the current pose of `part` at the current frame, or with no part
// (kNoPart) of every part with a skeleton. Returns the parts keyed.
int insertKeys(Document& document, PartId part);
// Returns the keys deleted (those still in the active clips).
int deleteKeys(Document& document, const KeySelection& keys);
KeyClipboard copyKeys(const Document& document, const KeySelection& keys);
// Pastes at the current frame into the parts the keys came from; keys copied
// from one part go into `target` instead when given and its skeleton has
// every joint they rotate. Returns the pasted keys' exact times (the new
// selection); parts gone or not fitting are skipped.
KeySelection pasteKeys(Document& document, const KeyClipboard& clipboard, PartId target = kNoPart);

}  // namespace rigmesh::model
