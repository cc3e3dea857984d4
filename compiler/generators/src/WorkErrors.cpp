#include "voxc/generators/WorkErrors.h"

#include <fmt/format.h>

namespace voxc::generators {

LimitError::LimitError(std::string_view generator, std::string quantity_, uint64_t value_, uint64_t limit_)
    : UserError(fmt::format("{}: {} is {}, over the limit of {}", generator, quantity_, value_, limit_)),
      quantity(std::move(quantity_)), value(value_), limit(limit_) {}

ParameterError::ParameterError(std::string_view generator, std::string parameter_, double value_,
                               std::string requirement_)
    : UserError(fmt::format("{}: {} = {} is invalid: {}", generator, parameter_, value_, requirement_)),
      parameter(std::move(parameter_)), value(value_), requirement(std::move(requirement_)) {}

} // namespace voxc::generators
