// The exit statuses of both command-line tools, `wavecontact` and `wavecontact-derive`
// (docs/cli.md lists them). Every failure maps onto one of these; 1 is reserved for what
// should not happen (a bug: the fuzzers report it as a finding).
#pragma once

namespace wavecontact::exit_status {

inline constexpr int success = 0;
inline constexpr int internal_error = 1;   // a bug
inline constexpr int bad_argument = 2;     // usage, an invalid or out-of-range value, a refused profile
inline constexpr int not_the_contact = 3;  // the single zone asked for is not the contact (p < 0 or gap < 0)
inline constexpr int beyond_reach = 4;     // not within tolerance, work budget spent, interrupted
inline constexpr int io_error = 5;         // output that cannot be written, a helper program that fails

}  // namespace wavecontact::exit_status
