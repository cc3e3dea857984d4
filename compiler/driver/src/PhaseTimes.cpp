#include "PhaseTimes.h"

#include <fmt/format.h>

namespace voxc::driver {

PhaseTimes::Phase& PhaseTimes::phase(const std::string& name) {
    for (Phase& p : phases_)
        if (p.name == name) return p;
    phases_.push_back({name, 0.0, ""});
    return phases_.back();
}

void PhaseTimes::add(const std::string& name, double ms, std::string note) {
    Phase& p = phase(name);
    p.ms += ms;
    if (!note.empty()) p.note = std::move(note);
}

void PhaseTimes::split(const std::string& from, const std::string& to, double ms, std::string note) {
    phase(from).ms -= ms;
    add(to, ms, std::move(note));
}

std::string PhaseTimes::format() const {
    std::string out = "timings (ms):\n";
    double total = 0.0;
    for (const Phase& p : phases_) {
        out += fmt::format("  {:<12} {:>9.1f}{}\n", p.name, p.ms, p.note.empty() ? "" : "  " + p.note);
        total += p.ms;
    }
    return out + fmt::format("  {:<12} {:>9.1f}\n", "total", total);
}

} // namespace voxc::driver
