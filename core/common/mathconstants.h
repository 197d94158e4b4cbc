#pragma once

namespace dd {

// π, once for every file that turns revolutions into radians or frequencies into phase.
inline constexpr double Pi = 3.14159265358979323846;

} // namespace dd
