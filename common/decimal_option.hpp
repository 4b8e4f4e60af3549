// Numbers on the command line are decimals, in both tools: "064" is not octal 52 nor 64,
// "0x10" not hex, "inf" and "nan" not numbers. CLI11 converts integers with strtoll(base 0)
// and reals with strtold (which reads hex floats), so every numeric option is checked
// against the decimal grammar before it is converted.
#pragma once

#include <cctype>
#include <string>

#include <CLI/CLI.hpp>

namespace wavecontact::cli_common {

namespace detail {

// Digits from `i`; returns how many.
inline std::size_t digits(const std::string& s, std::size_t& i) {
  const std::size_t start = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  return i - start;
}

// [+-]? integer part, with no leading zero unless it is "0"; returns false if ambiguous.
inline bool integer_part(const std::string& s, std::size_t& i, std::size_t& count) {
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t start = i;
  count = digits(s, i);
  return !(count > 1 && s[start] == '0');
}

}  // namespace detail

// An empty string if `s` is a decimal integer, else why not.
inline std::string decimal_integer_error(const std::string& s) {
  std::size_t i = 0, count = 0;
  if (!detail::integer_part(s, i, count)) return "a decimal integer without leading zeros";
  if (count == 0 || i != s.size()) return "a decimal integer";
  return {};
}

// An empty string if `s` is a decimal real ([+-]digits[.digits][e[+-]digits]), else why not.
inline std::string decimal_real_error(const std::string& s) {
  std::size_t i = 0, count = 0;
  if (!detail::integer_part(s, i, count)) return "a decimal number without leading zeros";
  std::size_t fraction = 0;
  if (i < s.size() && s[i] == '.') fraction = detail::digits(s, ++i);
  if (count + fraction == 0) return "a decimal number";
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (detail::digits(s, i) == 0) return "a decimal number";
  }
  return i == s.size() ? std::string{} : "a decimal number";
}

// Echoes at most about 200 characters of an input in a message.
inline std::string shortened(const std::string& s, std::size_t limit = 200) {
  return s.size() <= limit ? s : s.substr(0, limit) + "... (" + std::to_string(s.size()) + " characters)";
}

// CLI11 validators: each element of a (comma) list is checked.
inline CLI::Validator decimal_integer() {
  return CLI::Validator(
      [](std::string& s) {
        const std::string why = decimal_integer_error(s);
        return why.empty() ? std::string{} : "\"" + shortened(s) + "\" is not " + why;
      },
      "INTEGER", "decimal integer");
}

inline CLI::Validator decimal_real() {
  return CLI::Validator(
      [](std::string& s) {
        const std::string why = decimal_real_error(s);
        return why.empty() ? std::string{} : "\"" + shortened(s) + "\" is not " + why;
      },
      "NUMBER", "decimal number");
}

// Checks every numeric option of `app` and of its subcommands (by CLI11's type name: INT or
// FLOAT, alone or in a list) against the decimal grammar.
inline void require_decimal_numbers(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type.find("FLOAT") != std::string::npos) {
      option->check(decimal_real());
    } else if (type.find("INT") != std::string::npos) {
      option->check(decimal_integer());
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) require_decimal_numbers(*sub);
}

}  // namespace wavecontact::cli_common
