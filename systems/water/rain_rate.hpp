#pragma once
// How hard it rains, and how many drops that is (wave.model = capillary).
//
// Drop sizes follow Marshall and Palmer (1948), "The distribution of raindrops with size": N(D) =
// N0 exp(-lambda D) with lambda = 4.1 R^-0.21 per mm at R mm/h, here truncated to 1 to 4 mm (drops
// under 1 mm make rings too small to see at a pixel's 1 to 2 mm). A rate R brings R mm of water an hour:
// R * 1e6 / 3600 mm^3 a square metre a second, in drops of mean volume pi/6 E[D^3].

namespace puddle::systems {

inline constexpr double min_drop_mm = 1.0;
inline constexpr double max_drop_mm = 4.0;

// lambda of Marshall-Palmer at rate_mm_h (clamped to at least 0.01 mm/h), in 1/mm.
double marshall_palmer_slope(double rate_mm_h);

// Impacts per square metre per second at rate_mm_h in drops of 1 to 4 mm; 0 for a rate of 0 or less.
double impacts_per_square_metre_second(double rate_mm_h);

// The rain rate at time_s (seconds of the simulation clock, so screens on a shared clock agree): rate
// times a slow factor that wanders between 2^(-2 drift) and 2^(1.32 drift) as the sum of three sines of
// incommensurate periods (6.1, 17.3 and 41.9 minutes), which never repeats within an hour; drift 0 keeps
// it at rate.
double rain_rate_at(double rate_mm_h, double drift, double time_s);

}  // namespace puddle::systems
