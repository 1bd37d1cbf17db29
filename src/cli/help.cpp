// The command line's help (help.hpp): the entries of help_entries.cpp, the
// definitions they share, and which help an argv asks for.
#include "cli/help.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "cli/help_entries.hpp"
#include "cli/options.hpp"

namespace rocking::cli {

namespace {

const char* kBlockDefinitions = R"(
The block (eqs. 2, 4):
  B, H              its full thickness and full height (m); h = H/2, its half-height (eq. 2's H)
  alpha             its slenderness, alpha = atan(B/H) (rad)
  R                 its half-diagonal, R = sqrt(B^2 + H^2)/2 = h/cos(alpha) (m)
  p                 its pulsation (eq. 4), p = sqrt(3 g/(4 R)) (rad/s), g = 9.81 m/s^2: a taller
                    block has a lower p
  q                 q = PGA/(alpha g) (eq. 5): the input's peak acceleration over alpha g, at which
                    the block starts to rock on eq. 3 (g tan(alpha) on eq. 1)
  x                 x = p to, to the input's half-period (s); a record's to_5 = pi PGV/PGA (eq. 31)
)";

const char* kModelDefinitions = R"(
The model, unless said otherwise above: linearised eq. 3, exact solver (closed form between
events); at each impact theta' times Housner's restitution 1 - 1.5 sin^2 alpha; collapse is
overturning: the block falls (|theta| reaches pi/2) at any time, the free rocking after the input
followed (ground at rest, up to 200/p s; a block still rocking then is judged by its energy).
simulate --paper sets restitution 1 and the final-rotation criterion
(|theta(t_fin)| >= alpha at the input's end t_fin): the paper's Section 3 setting.
)";

const char* kRecordDefinitions = R"(
Records, read by content: ESM/ITACA ASCII or PEER AT2 (each states its unit and step), or plain
text ('#' lines skipped; comma, space or tab separated) of one column (give --unit U and the step
--dt DT in s; simulate: --record-dt) or two, time (s) and acceleration (give --unit U); U = g,
m/s2 or cm/s2. --unit and --dt apply to plain text only. Decimal commas are refused. A FILE may
be a pipe, a FIFO or /dev/stdin (not under mpirun): read once, up to 256 MiB, lines up to 1 MiB,
10 s of silence at most. PGA in m/s^2 (in g over 9.81 m/s^2), PGV in m/s.
)";

const char* kFloorDefinitions = R"(
A floor (--floor T1,G[,zeta]): the motion of a floor in place of the ground's, for an element at
height (a parapet on a roof), the building as its first mode: a linear oscillator of period T1 (s,
above 2 dt) and damping ratio zeta (in [0, 1), default 0.05) driven by the record, G = Gamma phi(z)
the floor's participation in that mode (3N/(2N + 1) at the roof of N equal storeys with a linear
mode shape); a_f = a_g + G D'' (docs/floor_motion.md; rocking record floor writes it to a file).
The outputs name the floor's model with the record.
)";

const char* kBeyondThePaperDefinitions = R"(
Beyond the paper's block (issue 41), on simulate and every study, stated in each output:
--friction MU       the base on Coulomb friction MU, in (0, 1e6]: the sliding-rocking model (full
                    equations; rest, slide, rock, slide-rock; impacts without rebound, the new
                    corner stuck or slipping), its own event-driven solver (docs/sliding.md)
--lean RAD          the block stands on a bed inclined by RAD toward theta > 0: alpha - RAD and
                    alpha + RAD on its two corners, the same p and restitution
--out-of-plumb RAD  a wall built leaning by RAD toward theta > 0 on a horizontal bed: each corner
                    its own alpha, p and restitution (docs/imperfect.md)
--fc MPA            the masonry's compressive strength: the pivots set back by half the
                    compressed zone (NTC 2018 eq. 7.8.2: 0.85 fc under the block's own weight,
                    --density KG/M3, default 1800); a base that crushes is refused
The imperfections combine (IMPERFECT in the usage: [--lean RAD] [--out-of-plumb RAD] [--fc MPA
[--density KG/M3]]); none goes with --friction. Angles within (-pi/4, pi/4).
)";

// A text of the help without the line break it starts with in the source.
std::string body(const char* text) { return text[0] == '\n' ? text + 1 : text; }

// "rocking record synth ...": the form's lines, each as the overview prints it.
std::vector<std::string> lines_of(const char* text) {
    std::vector<std::string> lines;
    std::istringstream in(body(text));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

const HelpEntry* entry_of(const std::string& topic) {
    for (const HelpEntry& e : help_entries())
        if (topic == e.topic) return &e;
    return nullptr;
}

// The synopsis under "usage: " (the first line) and its seven blanks (the others).
std::string synopsis_block(const std::vector<const HelpEntry*>& entries) {
    std::string out;
    for (const HelpEntry* e : entries)
        for (const std::string& line : lines_of(e->synopsis))
            out += (out.empty() ? "usage: " : "       ") + line + "\n";
    return out;
}

std::string commands() {
    std::string names;
    for (const HelpEntry& e : help_entries()) names += (names.empty() ? "" : ", ") + std::string(e.topic);
    return names;
}

std::string entry_help(const HelpEntry& e) {
    std::string out = synopsis_block({&e}) + "\n" + body(e.details);
    if (e.shared & kTheBlock) out += "\n" + body(kBlockDefinitions);
    if (e.shared & kTheModel) out += "\n" + body(kModelDefinitions);
    if (e.shared & kTheRecords) out += "\n" + body(kRecordDefinitions);
    if (e.shared & kTheFloor) out += "\n" + body(kFloorDefinitions);
    if (e.shared & kBeyondThePaper) out += "\n" + body(kBeyondThePaperDefinitions);
    return out;
}

// `rocking record --help`: the three record commands' synopses.
std::string record_help() {
    std::vector<const HelpEntry*> records;
    for (const HelpEntry& e : help_entries())
        if (std::string(e.topic).rfind("record ", 0) == 0) records.push_back(&e);
    return synopsis_block(records) +
           "\nEach one's options and definitions: rocking record info --help, rocking record synth --help,\n"
           "rocking record floor --help.\n";
}

bool asks_help(const std::string& arg) { return arg == "--help" || arg == "-h"; }

}  // namespace

std::string topic_of(int argc, char** argv) {
    if (argc < 2) return "";
    const std::string command = argv[1];
    if (command == "record") {
        const std::string sub = argc > 2 ? argv[2] : "";
        return entry_of("record " + sub) ? "record " + sub : "record";
    }
    return entry_of(command) ? command : "";
}

std::optional<std::string> help_request(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "help") {
        // rocking help record floor: the words after "help" are the topic.
        std::string topic;
        for (int i = 2; i < argc && i < 4; ++i) topic += (topic.empty() ? "" : " ") + std::string(argv[i]);
        if (topic.rfind("record ", 0) != 0 && argc > 2) topic = argv[2];
        return topic == "help" || asks_help(topic) ? "" : topic;
    }
    bool help = false;
    for (int i = 1; i < argc; ++i) help = help || asks_help(argv[i]);
    if (!help) return std::nullopt;
    if (asks_help(command)) return "";
    const std::string topic = topic_of(argc, argv);
    return topic.empty() ? command : topic;
}

std::string help_text(const std::string& topic) {
    if (topic.empty()) return overview();
    if (topic == "record") return record_help();
    if (const HelpEntry* e = entry_of(topic)) return entry_help(*e);
    throw UsageError("no command '" + topic + "' (the commands: " + commands() + ")");
}

std::string overview() {
    std::vector<const HelpEntry*> all;
    for (const HelpEntry& e : help_entries()) all.push_back(&e);
    return synopsis_block(all) +
           "\nIMPERFECT = [--lean RAD] [--out-of-plumb RAD] [--fc MPA [--density KG/M3]]: an imperfect block\n"
           "(not with --friction; 'rocking help simulate', Beyond the paper's block).\n"
           "\nEach command's options, with units and defaults, and the definitions it uses (alpha, p, q, the\n"
           "model, the records): 'rocking COMMAND --help', -h or 'rocking help COMMAND', e.g.\n"
           "'rocking assess --help', 'rocking record floor --help'. Every command but batch takes --json.\n"
           "Exit 0 with an answer, 2 on a bad argument, 1 on an input that cannot be answered (batch: 3\n"
           "when some job failed).\n"
           "mpirun: spectrum, fragility, eq27 and batch share their work across the ranks; the other commands\n"
           "refuse to start under mpirun (exit 2), as does an input on standard input or a pipe, which the\n"
           "ranks cannot share (save it to a file).\n";
}

std::string usage_line(const std::string& topic) {
    const HelpEntry* e = entry_of(topic);
    if (!e) return "usage: rocking " + topic;
    std::string line = "usage:";
    bool first = true;
    for (const std::string& text : lines_of(e->synopsis)) {
        const bool continues = text.rfind(' ', 0) == 0;
        if (!first && !continues) break;  // the next form
        first = false;
        line += " " + text.substr(text.find_first_not_of(' '));
    }
    return line;
}

}  // namespace rocking::cli
