// The command line's help (issue 40, item 7): `rocking --help` gives every
// command's synopsis; `rocking COMMAND --help`, `-h` or `rocking help COMMAND`
// gives that command's alone, its options with units and defaults, and the
// definitions it relies on (the block, the model, the records).  The
// synopses are also the one-line usages the commands' errors quote, so that
// an error and the help cannot disagree.
#pragma once

#include <optional>
#include <string>

namespace rocking::cli {

// The help argv asks for: "" for the overview (`rocking --help`, `rocking
// help`), a topic ("assess", "record floor", "record" for the three record
// commands, or an unknown name, which help_text refuses); nullopt when argv
// asks for none.  Any argument --help or -h asks for it: no option takes a
// value spelled like this.
std::optional<std::string> help_request(int argc, char** argv);

// The text to print for a request of help_request: the overview for "",
// the topic's help otherwise; a UsageError naming the commands for a topic
// that is none.
std::string help_text(const std::string& topic);

// The overview: every command's synopsis, and how to get a command's details.
std::string overview();

// "usage: rocking TOPIC ...": the topic's first form on one line, for its
// errors (a missing FILE, an option before it).
std::string usage_line(const std::string& topic);

// The topic of the command argv runs ("record synth" for `rocking record
// synth ...`), for the pointer after a usage error; "" when argv names none.
std::string topic_of(int argc, char** argv);

}  // namespace rocking::cli
