// The help's entries (help_entries.cpp), one a command, for help.cpp to
// assemble: what a command's help holds beside the shared definitions.
#pragma once

#include <vector>

namespace rocking::cli {

// The shared definitions a command relies on, appended to its details.
enum SharedDefinitions : unsigned {
    kTheBlock = 1u,       // alpha = atan(B/H), R, p (eq. 4), q = PGA/(alpha g), x = p to
    kTheModel = 2u,       // the default model: Housner's restitution, overturning after the free rocking
    kTheRecords = 4u,     // the records' formats, units, --unit and --dt
    kTheFloor = 8u,       // --floor T1,G[,zeta]
    kBeyondThePaper = 16u,  // --friction, --lean, --out-of-plumb, --fc, --density (issue 41)
};

// Each text starts with a line break, dropped (so that its first line lines up with the rest
// in the source).
struct HelpEntry {
    const char* topic;     // "assess", "record floor"
    // Its forms, one a line: the first starts "rocking TOPIC", a line that
    // continues a form starts with blanks, aligned after the prefix "usage: "
    // or its seven blanks; another form starts "rocking" or "mpirun".
    const char* synopsis;
    const char* details;   // what it does, then every option with units and defaults
    unsigned shared;       // SharedDefinitions appended after the details
};

// Every command's entry, in the overview's order.
const std::vector<HelpEntry>& help_entries();

}  // namespace rocking::cli
