#include "voxc/generators/lsystem/Export.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace voxc::lsystem {

namespace {

using Json = nlohmann::ordered_json;

Json point(glm::dvec3 p) { return Json::array({p.x, p.y, p.z}); }

void appendVertex(std::string& out, glm::dvec3 p) { out += fmt::format("v {} {} {}\n", p.x, p.y, p.z); }

// Writes the vertices of one polyline and its `l` element; `next` is the next vertex index.
void appendPolyline(std::string& out, const std::vector<glm::dvec3>& points, size_t& next) {
    for (const glm::dvec3& p : points) appendVertex(out, p);
    out += 'l';
    for (size_t i = 0; i < points.size(); ++i) out += fmt::format(" {}", next + i);
    out += '\n';
    next += points.size();
}

} // namespace

std::string skeletonJson(const Skeleton& skeleton) {
    Json json;
    json["segments"] = Json::array();
    for (const Segment& s : skeleton.segments)
        json["segments"].push_back({{"from", point(s.from)},
                                    {"to", point(s.to)},
                                    {"branch", s.branch},
                                    {"type", std::string(symbolTypeName(s.type))},
                                    {"radius", s.radius}});
    json["endpoints"] = Json::array();
    for (const Endpoint& e : skeleton.endpoints) json["endpoints"].push_back({{"position", point(e.position)}, {"branch", e.branch}});
    json["branches"] = Json::array();
    for (const Branch& b : skeleton.branches)
        json["branches"].push_back({{"parent", b.parent}, {"no_connect", b.noConnect}, {"cut", b.cut}});
    json["connections"] = Json::array();
    for (const Connection& c : skeleton.connections) {
        Json points = Json::array();
        for (const glm::dvec3& p : c.points) points.push_back(point(p));
        json["connections"].push_back({{"from", c.from}, {"to", c.to}, {"points", std::move(points)}});
    }
    json["final_position"] = point(skeleton.finalPosition);
    json["start_outside"] = skeleton.startOutside;
    return json.dump(1) + "\n";
}

std::string skeletonObj(const Skeleton& skeleton) {
    std::string out = fmt::format("# voxc L-system skeleton: {} segments, {} endpoints, {} connections\n",
                                  skeleton.segments.size(), skeleton.endpoints.size(), skeleton.connections.size());
    size_t next = 1; // OBJ indices are 1-based
    out += "o skeleton\n";
    std::vector<glm::dvec3> run;
    uint32_t branch = 0;
    for (const Segment& s : skeleton.segments) {
        if (run.empty() || s.from != run.back() || s.branch != branch) {
            if (!run.empty()) appendPolyline(out, run, next);
            run = {s.from};
            branch = s.branch;
        }
        run.push_back(s.to);
    }
    if (!run.empty()) appendPolyline(out, run, next);
    if (!skeleton.connections.empty()) out += "o connections\n";
    for (const Connection& c : skeleton.connections) appendPolyline(out, c.points, next);
    return out;
}

} // namespace voxc::lsystem
