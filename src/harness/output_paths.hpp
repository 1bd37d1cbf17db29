// What a command checks of the files it will write before its first
// simulation (issue 38): an output that is one of its inputs would replace
// the input (batch study.csv --output study.csv replaced the manifest), two
// outputs that are one file keep only the last, and a path that cannot be
// written was found only after the work it was meant to keep.
#pragma once

#include <string>
#include <vector>

namespace rocking::harness {

// A path and how the user named it, for the messages: "--output", "--png",
// "FILE", "the manifest", "row 4's record".
struct NamedPath {
    std::string role;
    std::string path;
};

// Whether a and b are one regular file: the same device and inode, whatever
// the spelling, links included.  False when either is absent or is not a
// regular file (/dev/stdout twice is not one file to protect).
bool same_file(const std::string& a, const std::string& b);

// Throws std::invalid_argument naming both paths when an output is one of
// the inputs, or two outputs would land on one file (compared by inode when
// it exists, otherwise by its folder's canonical path and its name).
void refuse_outputs_over_inputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// Throws std::invalid_argument "ROLE: an empty file name" for an empty path: a bad
// argument, which no folder's state explains (--output '' ran a whole simulation,
// then failed to move its temporary file onto "").
void refuse_empty_name(const NamedPath& output);

// refuse_empty_name, then throws std::runtime_error "ROLE: PATH: reason" when the output cannot be
// written as AtomicFile writes it: a temporary file beside it is created and
// removed.  A target that exists and is not a regular file (a device, a
// FIFO) is only checked for write permission: opening a FIFO now would hand
// its reader an end of file before the real output.
void check_writable(const NamedPath& output);

// Every check, before any work: no empty name, the outputs against the inputs
// and each other, then each output's folder.
void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace rocking::harness
