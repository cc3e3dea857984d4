#include "Constants.h"

#include "Suggest.h"

#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace voxc::check {

void Constants::declare(const ast::ConstDecl& decl) {
    if (auto it = entries_.find(decl.name); it != entries_.end()) {
        diagnostics_.error("E0003", decl.loc, fmt::format("constant '{}' is already declared", decl.name),
                           {{it->second.loc, "first declared here"}});
        return;
    }
    std::optional<double> value = decl.value ? evaluate(*decl.value) : std::nullopt;
    if (auto it = overrides_.find(decl.name); it != overrides_.end()) {
        value = it->second;
        // A NaN would pass every range check (comparisons with it are false) and reach the program.
        if (!std::isfinite(*value)) {
            diagnostics_.error("E0007", decl.loc,
                               fmt::format("the override of constant '{}' is {}, not a finite number", decl.name,
                                           *value));
            value = std::nullopt;
        }
    }
    entries_.emplace(decl.name, Entry{decl.loc, value});
}

void Constants::reportUnknownOverrides() const {
    std::vector<std::string_view> names;
    for (const auto& entry : entries_) names.push_back(entry.first);
    for (const auto& [name, value] : overrides_) {
        if (isDeclared(name)) continue;
        diagnostics_.error("E0002", {},
                           fmt::format("cannot override constant '{}': the file declares no such constant{}", name,
                                       names.empty() ? std::string(" (it declares none)") : suggestOrList(name, names)));
    }
}

std::optional<double> Constants::evaluate(const ast::Expr& expr, std::string_view subject) const {
    bool failed = false;
    std::optional<double> value = fold(expr, subject, failed);
    if (failed || !value) return std::nullopt;
    return value;
}

std::optional<double> Constants::fold(const ast::Expr& expr, std::string_view subject, bool& failed) const {
    using Kind = ast::Expr::Kind;
    auto checked = [&](double v) -> std::optional<double> {
        if (std::isfinite(v)) return v;
        diagnostics_.error("E0007", expr.loc, "value is too large to represent");
        failed = true;
        return std::nullopt;
    };
    switch (expr.kind) {
    case Kind::Number: return checked(expr.number);
    case Kind::Name: {
        auto it = entries_.find(expr.name);
        if (it != entries_.end()) {
            if (!it->second.value) failed = true; // already reported at its declaration
            return it->second.value;
        }
        std::vector<std::string_view> names;
        if (errorsStillShown(diagnostics_))
            for (const auto& entry : entries_) names.push_back(entry.first);
        diagnostics_.error("E0002", expr.loc,
                           fmt::format("unknown constant '{}'{}", expr.name, didYouMean(expr.name, names)));
        failed = true;
        return std::nullopt;
    }
    case Kind::String:
        diagnostics_.error("E0010", expr.loc,
                           subject.empty()
                               ? fmt::format("expected a number, found the string \"{}\"", expr.name)
                               : fmt::format("{} expects a number, found the string \"{}\"", subject, expr.name));
        failed = true;
        return std::nullopt;
    case Kind::Negate: {
        auto operand = fold(*expr.lhs, subject, failed);
        return operand ? std::optional<double>(-*operand) : std::nullopt;
    }
    default: break;
    }
    auto lhs = fold(*expr.lhs, subject, failed);
    auto rhs = fold(*expr.rhs, subject, failed);
    if (!lhs || !rhs) return std::nullopt;
    switch (expr.kind) {
    case Kind::Add: return checked(*lhs + *rhs);
    case Kind::Subtract: return checked(*lhs - *rhs);
    case Kind::Multiply: return checked(*lhs * *rhs);
    case Kind::Divide:
        if (*rhs == 0.0) {
            diagnostics_.error("E0007", expr.rhs->loc, "division by zero");
            failed = true;
            return std::nullopt;
        }
        return checked(*lhs / *rhs);
    default: return std::nullopt;
    }
}

} // namespace voxc::check
