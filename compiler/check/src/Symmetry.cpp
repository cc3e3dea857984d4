#include "Symmetry.h"

#include "Suggest.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::check {

namespace {

using Element = SymmetryElement;

constexpr Element kIdentity{};

// The square group about y (y kept), in the order variants are generated.
struct NamedElement {
    std::string_view name;
    Element element;
};
constexpr NamedElement kSquare[] = {
    {"identity", {{0, 1, 2}, {false, false, false}}},
    {"rot90y", {{2, 1, 0}, {false, false, true}}},  // x' = z, z' = -x: a right-handed quarter turn about +y
    {"rot180y", {{0, 1, 2}, {true, false, true}}},
    {"rot270y", {{2, 1, 0}, {true, false, false}}},
    {"mirror_x", {{0, 1, 2}, {true, false, false}}},
    {"mirror_z", {{0, 1, 2}, {false, false, true}}},
    {"mirror_diag", {{2, 1, 0}, {false, false, false}}},    // x' = z, z' = x
    {"mirror_antidiag", {{2, 1, 0}, {true, false, true}}}, // x' = -z, z' = -x
};

bool sameElement(const Element& a, const Element& b) { return a.from == b.from && a.negate == b.negate; }

Element withMirrorY(Element e) {
    e.negate[1] = !e.negate[1];
    return e;
}

const NamedElement& squareElement(std::string_view name) {
    for (const NamedElement& named : kSquare)
        if (named.name == name) return named;
    throw std::logic_error("no square element named " + std::string(name));
}

std::vector<Element> elementsNamed(std::initializer_list<std::string_view> names) {
    std::vector<Element> out;
    for (std::string_view name : names) out.push_back(squareElement(name).element);
    return out;
}

// Every signed permutation: the square group, then it with y mirrored, then the 32 that move y.
std::vector<Element> cubeGroup() {
    std::vector<Element> out;
    for (const NamedElement& named : kSquare) out.push_back(named.element);
    for (const NamedElement& named : kSquare) out.push_back(withMirrorY(named.element));
    std::array<int, 3> from{0, 1, 2};
    do {
        if (from[1] == 1) continue; // y stays y: listed above
        for (int signs = 0; signs < 8; ++signs)
            out.push_back({from, {(signs & 1) != 0, (signs & 2) != 0, (signs & 4) != 0}});
    } while (std::next_permutation(from.begin(), from.end()));
    return out;
}

// Names a list form may use: the square group and each of it with y mirrored.
std::vector<std::string> listableNames() {
    std::vector<std::string> names;
    for (const NamedElement& named : kSquare) names.emplace_back(named.name);
    for (const NamedElement& named : kSquare) names.push_back(withMirrorY(named.element).name());
    return names;
}

std::optional<Element> elementByName(std::string_view name) {
    for (const NamedElement& named : kSquare) {
        if (named.name == name) return named.element;
        const Element flipped = withMirrorY(named.element);
        if (flipped.name() == name) return flipped;
    }
    return std::nullopt;
}

constexpr std::string_view kGroupNames[] = {"none", "x", "z", "xz", "xyz", "rot_y", "square", "all"};

bool sameSymbol(const SymbolCell& a, const SymbolCell& b) {
    const auto samePredicate = [](const Predicate& p, const Predicate& q) {
        return p.op == q.op && (p.value == q.value || (std::isnan(p.value) && std::isnan(q.value)));
    };
    const auto sameMaterial = [](const MaterialPredicate& p, const MaterialPredicate& q) {
        return p.op == q.op && p.material == q.material;
    };
    return std::equal(a.predicates.begin(), a.predicates.end(), b.predicates.begin(), b.predicates.end(),
                      samePredicate) &&
           std::equal(a.materialPredicates.begin(), a.materialPredicates.end(), b.materialPredicates.begin(),
                      b.materialPredicates.end(), sameMaterial);
}

bool sameTransform(const TransformCell& a, const TransformCell& b) {
    return a.op == b.op && a.value == b.value && a.material == b.material;
}

bool sameAggregate(const AggregateTest& a, const AggregateTest& b) {
    return a.kind == b.kind && a.boxMin == b.boxMin && a.boxMax == b.boxMax && a.material == b.material &&
           a.low == b.low && a.high == b.high && a.minCount == b.minCount && a.maxCount == b.maxCount;
}

bool sameWindow(const Rule& a, const Rule& b) {
    // A stamp turns with its variant even where the window does not, so such variants differ.
    const auto sameStamp = [](const Stamp& x, const Stamp& y) { return x.from == y.from && x.negate == y.negate; };
    return a.size == b.size &&
           std::equal(a.stamps.begin(), a.stamps.end(), b.stamps.begin(), b.stamps.end(), sameStamp) &&
           std::equal(a.aggregates.begin(), a.aggregates.end(), b.aggregates.begin(), b.aggregates.end(),
                      sameAggregate) &&
           std::equal(a.symbol.begin(), a.symbol.end(), b.symbol.begin(), b.symbol.end(), sameSymbol) &&
           std::equal(a.transform.begin(), a.transform.end(), b.transform.begin(), b.transform.end(), sameTransform);
}

} // namespace

bool SymmetryElement::isIdentity() const { return sameElement(*this, kIdentity); }

std::string SymmetryElement::name() const {
    for (const NamedElement& named : kSquare) {
        if (sameElement(*this, named.element)) return std::string(named.name);
        if (sameElement(*this, withMirrorY(named.element)))
            return named.name == "identity" ? "mirror_y" : std::string(named.name) + "_mirror_y";
    }
    std::string out = "[";
    for (int axis = 0; axis < 3; ++axis)
        out += fmt::format("{}{}{}", axis ? "," : "", negate[axis] ? "-" : "", "xyz"[from[axis]]);
    return out + "]";
}

std::optional<std::vector<SymmetryElement>> symmetryGroup(std::string_view name) {
    if (name == "none") return std::vector<Element>{kIdentity};
    if (name == "x") return elementsNamed({"identity", "mirror_x"});
    if (name == "z") return elementsNamed({"identity", "mirror_z"});
    if (name == "xz") return elementsNamed({"identity", "mirror_x", "mirror_z", "rot180y"});
    if (name == "rot_y") return elementsNamed({"identity", "rot90y", "rot180y", "rot270y"});
    if (name == "square") {
        std::vector<Element> out;
        for (const NamedElement& named : kSquare) out.push_back(named.element);
        return out;
    }
    if (name == "xyz") {
        std::vector<Element> out;
        for (int signs = 0; signs < 8; ++signs)
            out.push_back({{0, 1, 2}, {(signs & 1) != 0, (signs & 2) != 0, (signs & 4) != 0}});
        return out;
    }
    if (name == "all") return cubeGroup();
    return std::nullopt;
}

std::optional<std::vector<SymmetryElement>> readSymmetry(Context& context, const ast::Assignment& a) {
    const auto nameOf = [](const ast::Value& value) -> const std::string* {
        const ast::Expr* expr = value.isList() ? nullptr : value.scalar.get();
        return expr && expr->kind == ast::Expr::Kind::Name ? &expr->name : nullptr;
    };
    if (!a.value.isList()) {
        const std::string* name = nameOf(a.value);
        if (!name) {
            context.diagnostics.error("E0010", a.value.loc,
                                      "'symmetry' expects a group (none, x, z, xz, xyz, rot_y, square, all) or a "
                                      "list of elements such as [rot90y, mirror_x]");
            return std::nullopt;
        }
        auto group = symmetryGroup(*name);
        if (!group)
            context.diagnostics.error("E0002", a.value.loc,
                                      fmt::format("unknown symmetry group '{}'{}", *name,
                                                  suggestOrList(*name, kGroupNames)));
        return group;
    }
    std::vector<Element> elements{kIdentity};
    bool ok = true;
    for (const ast::Value& value : a.value.elements) {
        const std::string* name = nameOf(value);
        std::optional<Element> element = name ? elementByName(*name) : std::nullopt;
        if (element) {
            elements.push_back(*element);
            continue;
        }
        ok = false;
        if (!name) {
            context.diagnostics.error("E0010", value.loc, "a symmetry element is a name such as rot90y or mirror_x");
            continue;
        }
        const std::vector<std::string> names = listableNames();
        const std::vector<std::string_view> candidates(names.begin(), names.end());
        context.diagnostics.error("E0002", value.loc,
                                  fmt::format("unknown symmetry element '{}'{}", *name,
                                              suggestOrList(*name, candidates)));
    }
    if (!ok) return std::nullopt;
    return elements;
}

CheckedRule applySymmetry(const CheckedRule& original, const SymmetryElement& element) {
    const Rule& rule = original.rule;
    CheckedRule out = original;
    out.rule.name = rule.name + "@" + element.name();
    out.syntax.isVariant = true;
    const glm::ivec3 size = rule.size;
    glm::ivec3 variantSize;
    for (int axis = 0; axis < 3; ++axis) variantSize[axis] = size[element.from[axis]];
    out.rule.size = variantSize;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                // Doubled coordinates about the window's centre stay integers for even extents.
                const glm::ivec3 centred = 2 * glm::ivec3(x, y, z) - (size - 1);
                glm::ivec3 moved;
                for (int axis = 0; axis < 3; ++axis) {
                    const int c = centred[element.from[axis]];
                    moved[axis] = (element.negate[axis] ? -c : c) + variantSize[axis] - 1;
                }
                moved /= 2;
                const int from = cellIndex(size, x, y, z);
                const int to = cellIndex(variantSize, moved.x, moved.y, moved.z);
                out.rule.symbol[to] = rule.symbol[from];
                out.rule.transform[to] = rule.transform[from];
                out.syntax.symbolCells[to] = original.syntax.symbolCells[from];
            }
    // An aggregate's box turns with the window: a mirrored axis maps [lo, hi) to [size - hi, size - lo).
    for (AggregateTest& test : out.rule.aggregates) {
        const AggregateTest before = test;
        for (int axis = 0; axis < 3; ++axis) {
            const int from = element.from[axis];
            test.boxMin[axis] = element.negate[axis] ? size[from] - before.boxMax[from] : before.boxMin[from];
            test.boxMax[axis] = element.negate[axis] ? size[from] - before.boxMin[from] : before.boxMax[from];
        }
    }
    // A stamp keeps the written rule's frame and reach, read through the element (voxc::stampLocal).
    for (Stamp& stamp : out.rule.stamps) {
        const glm::ivec3 reach = stamp.reach;
        for (int axis = 0; axis < 3; ++axis) {
            stamp.from[axis] = element.from[axis];
            stamp.negate[axis] = element.negate[axis];
            stamp.reach[axis] = reach[element.from[axis]];
        }
    }
    return out;
}

std::vector<CheckedRule> expandSymmetry(const CheckedRule& rule, const std::vector<SymmetryElement>& elements) {
    std::vector<CheckedRule> out{rule};
    for (const SymmetryElement& element : elements) {
        if (element.isIdentity()) continue;
        CheckedRule variant = applySymmetry(rule, element);
        const bool seen = std::any_of(out.begin(), out.end(),
                                      [&](const CheckedRule& kept) { return sameWindow(kept.rule, variant.rule); });
        if (!seen) out.push_back(std::move(variant));
    }
    return out;
}

} // namespace voxc::check
