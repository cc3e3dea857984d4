#pragma once
// `voxc run --timings`: wall time per phase of a run, printed as one table at the end.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace voxc::driver {

class PhaseTimes {
public:
    // Runs `work`, adds its wall time to phase `name` (phases print in first-use order).
    template <typename Work>
    decltype(auto) time(const std::string& name, Work&& work) {
        const auto start = std::chrono::steady_clock::now();
        struct AddOnExit {
            PhaseTimes& times;
            const std::string& name;
            std::chrono::steady_clock::time_point start;
            ~AddOnExit() {
                times.add(name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            }
        } addOnExit{*this, name, start};
        return std::forward<Work>(work)();
    }
    void add(const std::string& name, double ms, std::string note = "");
    // Moves `ms` of phase `from` into a new phase `to` (a part measured inside another).
    void split(const std::string& from, const std::string& to, double ms, std::string note = "");
    // "timings (ms): ..." one line per phase, then the total.
    std::string format() const;

private:
    struct Phase {
        std::string name;
        double ms = 0.0;
        std::string note;
    };
    Phase& phase(const std::string& name);
    std::vector<Phase> phases_;
};

} // namespace voxc::driver
