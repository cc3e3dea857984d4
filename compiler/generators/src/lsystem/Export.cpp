#include "voxc/generators/lsystem/Export.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

namespace voxc::lsystem {

namespace {

using Json = nlohmann::ordered_json;

Json point(glm::dvec3 p) { return Json::array({p.x, p.y, p.z}); }

void writeVertex(std::ostream& out, glm::dvec3 p) { out << fmt::format("v {} {} {}\n", p.x, p.y, p.z); }

// Writes the vertices of one polyline and its `l` element; `next` is the next vertex index.
void writePolyline(std::ostream& out, const std::vector<glm::dvec3>& points, size_t& next) {
    for (const glm::dvec3& p : points) writeVertex(out, p);
    out << 'l';
    for (size_t i = 0; i < points.size(); ++i) out << fmt::format(" {}", next + i);
    out << '\n';
    next += points.size();
}

// `value` as nlohmann's dump(1) writes it `depth` levels deep: every line after the first
// indented by `depth` more spaces.
void writeNested(std::ostream& out, const Json& value, int depth) {
    const std::string text = value.dump(1);
    const std::string indent(size_t(depth), ' ');
    size_t begin = 0;
    for (size_t newline; (newline = text.find('\n', begin)) != std::string::npos; begin = newline + 1)
        out << std::string_view(text).substr(begin, newline + 1 - begin) << indent;
    out << std::string_view(text).substr(begin);
}

// One key of the top-level object: a list whose elements are made one at a time, so the
// document is never held whole (a skeleton of 2^22 segments is gigabytes as a JSON tree).
template <typename Items, typename Element>
void writeList(std::ostream& out, std::string_view key, const Items& items, Element element) {
    out << " \"" << key << "\": [";
    bool first = true;
    for (const auto& item : items) {
        out << (first ? "\n  " : ",\n  ");
        writeNested(out, element(item), 2);
        first = false;
    }
    out << (first ? "],\n" : "\n ],\n");
}

} // namespace

void writeSkeletonJson(std::ostream& out, const Skeleton& skeleton) {
    out << "{\n";
    writeList(out, "segments", skeleton.segments, [](const Segment& s) {
        return Json{{"from", point(s.from)},
                    {"to", point(s.to)},
                    {"branch", s.branch},
                    {"type", std::string(symbolTypeName(s.type))},
                    {"radius", s.radius}};
    });
    writeList(out, "endpoints", skeleton.endpoints,
              [](const Endpoint& e) { return Json{{"position", point(e.position)}, {"branch", e.branch}}; });
    writeList(out, "branches", skeleton.branches,
              [](const Branch& b) { return Json{{"parent", b.parent}, {"no_connect", b.noConnect}, {"cut", b.cut}}; });
    writeList(out, "connections", skeleton.connections, [](const Connection& c) {
        Json points = Json::array();
        for (const glm::dvec3& p : c.points) points.push_back(point(p));
        return Json{{"from", c.from}, {"to", c.to}, {"points", std::move(points)}};
    });
    out << " \"final_position\": ";
    writeNested(out, point(skeleton.finalPosition), 1);
    out << ",\n \"start_outside\": " << (skeleton.startOutside ? "true" : "false") << "\n}\n";
}

std::string skeletonJson(const Skeleton& skeleton) {
    std::ostringstream out;
    writeSkeletonJson(out, skeleton);
    return std::move(out).str();
}

void writeSkeletonObj(std::ostream& out, const Skeleton& skeleton) {
    out << fmt::format("# voxc L-system skeleton: {} segments, {} endpoints, {} connections\n",
                       skeleton.segments.size(), skeleton.endpoints.size(), skeleton.connections.size());
    size_t next = 1; // OBJ indices are 1-based
    out << "o skeleton\n";
    std::vector<glm::dvec3> run;
    uint32_t branch = 0;
    for (const Segment& s : skeleton.segments) {
        if (run.empty() || s.from != run.back() || s.branch != branch) {
            if (!run.empty()) writePolyline(out, run, next);
            run = {s.from};
            branch = s.branch;
        }
        run.push_back(s.to);
    }
    if (!run.empty()) writePolyline(out, run, next);
    if (!skeleton.connections.empty()) out << "o connections\n";
    for (const Connection& c : skeleton.connections) writePolyline(out, c.points, next);
}

std::string skeletonObj(const Skeleton& skeleton) {
    std::ostringstream out;
    writeSkeletonObj(out, skeleton);
    return std::move(out).str();
}

} // namespace voxc::lsystem
