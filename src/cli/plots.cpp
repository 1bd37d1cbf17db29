#include "cli/plots.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "harness/plot_file.hpp"
#include "harness/table.hpp"

namespace rocking::cli {

namespace {

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// A temporary file of ours, removed when it goes out of scope.
struct TempFile {
    std::string path;
    explicit TempFile(const std::string& stem) {
        std::string pattern = (std::filesystem::temp_directory_path() / (stem + ".XXXXXX")).string();
        const int fd = mkstemp(pattern.data());
        if (fd < 0) throw std::runtime_error("--png: cannot create a temporary file in " +
                                             std::filesystem::temp_directory_path().string());
        close(fd);
        path = pattern;
    }
    ~TempFile() { std::remove(path.c_str()); }
};

bool gnuplot_on_path() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

}  // namespace

std::string gp_string(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out += "''";
        else out += (c >= 0x20 && c < 0x7F) ? c : '?';
    }
    return out + "'";
}

std::string gp_text(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string gp_number(double v) { return harness::format_number(v); }

std::string datablock(const std::string& name, const std::vector<std::vector<double>>& rows) {
    std::string text = "$" + name + " << EOD\n";
    for (const std::vector<double>& row : rows) {
        for (std::size_t i = 0; i < row.size(); ++i) text += (i ? " " : "") + gp_number(row[i]);
        text += "\n";
    }
    return text + "EOD\n";
}

void require_gnuplot(const Args& a) {
    if (!a.values.count("--png")) return;
    if (!gnuplot_on_path())
        throw std::runtime_error("--png " + a.values.at("--png") + ": gnuplot is not installed (make deps)");
}

std::string Figure::terminal(const std::string& output) const {
    return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
           " font 'DejaVu Sans,11'\nset output " + gp_string(output) + "\n";
}

std::string Figure::screen(int x, int y) const {
    return "screen " + gp_number(static_cast<double>(x) / width) + ", screen " +
           gp_number(1 - static_cast<double>(y) / height);
}

std::string Figure::area(int left, int top, int right, int bottom) const {
    return "set lmargin at screen " + gp_number(static_cast<double>(left) / width) +
           "\nset rmargin at screen " + gp_number(static_cast<double>(right) / width) +
           "\nset tmargin at screen " + gp_number(1 - static_cast<double>(top) / height) +
           "\nset bmargin at screen " + gp_number(1 - static_cast<double>(bottom) / height) + "\n";
}

std::vector<std::string> wrapped(const std::string& text, std::size_t width) {
    std::vector<std::string> lines;
    std::istringstream words(text);
    std::string word, line;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            lines.push_back(line);
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

std::vector<double> round_values(double lo, double hi) {
    const std::vector<std::vector<double>> mantissas = {{1, 2, 5}, {1, 1.5, 2, 3, 4, 5, 6, 8}};
    std::vector<double> values;
    for (const std::vector<double>& set : mantissas) {
        values.clear();
        for (int e = static_cast<int>(std::floor(std::log10(lo))) - 1; e <= std::ceil(std::log10(hi)); ++e)
            for (double m : set) {
                // "2e-2" read back: the label's own double, not 2 * 10^-2 rounded twice.
                char text[32];
                std::snprintf(text, sizeof text, "%ge%d", m, e);
                const double v = std::strtod(text, nullptr);
                if (v >= lo && v <= hi) values.push_back(v);
            }
        if (values.size() >= 3 && values.size() <= 16) return values;
        if (values.size() > 16) {  // a wide range: the decades alone
            std::vector<double> decades;
            for (double v : values)
                if (std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-12) decades.push_back(v);
            return decades;
        }
    }
    values.clear();
    for (double v : {lo, std::sqrt(lo * hi), hi}) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", v);
        values.push_back(std::strtod(text, nullptr));
    }
    return values;
}

std::string log_tics(const std::string& axis, double lo, double hi) {
    std::string text = "set " + axis + "tics (";
    const std::vector<double> values = round_values(lo, hi);
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + gp_number(values[i]);
    return text + ")\n";
}

void draw_png(const std::string& png, const std::function<std::string(const std::string& output)>& script) {
    // Checked again here: gnuplot may have gone since the command was parsed,
    // and a library caller has no parse.
    if (!gnuplot_on_path()) throw std::runtime_error("--png " + png + ": gnuplot is not installed (make deps)");
    const TempFile file_of_script("rocking-plot-gp"), log("rocking-plot-log");
    std::unique_ptr<harness::PlotFile> file;
    try {
        file = std::make_unique<harness::PlotFile>(png);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("--png: ") + e.what());
    }
    const std::string text = script(file->draw_name());
    {
        std::ofstream out(file_of_script.path);
        out << text;
        if (!out.flush())
            throw std::runtime_error("--png " + png + ": cannot write the plot's script to " + file_of_script.path);
    }
    if (const char* keep = std::getenv("ROCKING_PLOT_SCRIPT"); keep && *keep) {
        std::ofstream out(keep);
        out << text;
        if (!out.flush()) throw std::runtime_error("--png " + png + ": cannot write ROCKING_PLOT_SCRIPT " + keep);
    }
    // gnuplot runs in the folder it draws in and names the file by its plain name:
    // the target's own name never reaches the script (PlotFile::draw_name).
    const std::string cmd = "cd " + shell_quote(file->draw_folder()) + " && gnuplot " +
                            shell_quote(file_of_script.path) + " 2>" + shell_quote(log.path);
    if (std::system(cmd.c_str()) != 0) {
        std::ifstream in(log.path);
        std::string first, line;
        while (std::getline(in, line))
            if (!line.empty()) first += (first.empty() ? "" : " | ") + line;
        throw std::runtime_error("--png " + png + ": gnuplot failed: " + first.substr(0, 400));
    }
    try {
        file->commit();
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("--png: ") + e.what());
    }
}

std::string caption_and_end(const Figure& fig, const std::vector<std::string>& lines, int footer) {
    std::ostringstream gp;
    for (std::size_t i = 0; i < lines.size(); ++i)
        gp << "set label " << 100 + i << " " << gp_text(lines[i]) << " at "
           << fig.screen(fig.width / 2, fig.height - footer + 16 + 16 * static_cast<int>(i)) << " center font ',10'\n";
    // The caption's labels are drawn by a plot: an empty one over the last panel's area.
    gp << "unset title\nunset xlabel\nunset ylabel\nunset tics\nunset border\nunset grid\nunset key\n"
       << "plot NaN notitle\nunset multiplot\n";
    return gp.str();
}

std::string typographic_quotes(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '\'' ? std::string("\u2019") : std::string(1, c);
    return out;
}

}  // namespace rocking::cli
