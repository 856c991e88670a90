// The hsx program's own checks of its inputs and outputs as a whole (commands.hpp).
#include "cli/commands.hpp"
#include <hsx/io/files.hpp>
#include <hsx/io/input.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace hsx::cli {
namespace {

/// A value given on the command line, and the option (or positional argument) it was given to.
struct NamedPath {
  std::string option, path;
};

bool is_output_option(CLI::Option* option) {
  try {
    option->get_validator(kOutputPathValidator);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

/// Every value of `app`'s options and of its parsed subcommands', outputs apart.
void collect(CLI::App* app, std::vector<NamedPath>& inputs, std::vector<NamedPath>& outputs) {
  for (CLI::Option* option : app->get_options())
    for (const std::string& value : option->results())
      (is_output_option(option) ? outputs : inputs).push_back({option->get_name(), value});
  for (CLI::App* sub : app->get_subcommands()) collect(sub, inputs, outputs);
}

/// read_integers_in_decimal's rewriting of one value: " +010 " -> "10"; an error for what is not a decimal whole
/// number within 64 bits (signed or not, as `is_signed` says).
CLI::Validator decimal_whole_number(bool is_signed) {
  return CLI::Validator(
      [is_signed](std::string& s) {
        const std::size_t first = s.find_first_not_of(' '), last = s.find_last_not_of(' ');
        std::string digits = first == std::string::npos ? "" : s.substr(first, last - first + 1);
        const bool negative = !digits.empty() && digits[0] == '-';
        if (!digits.empty() && (digits[0] == '+' || negative)) digits.erase(0, 1);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || (negative && !is_signed))
          return "must be a whole number written in decimal digits" + std::string(is_signed ? "" : " (>= 0)") +
                 ", not \"" + s + "\"";
        digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));  // "010" is ten, not eight
        const std::string most = is_signed ? (negative ? "9223372036854775808" : "9223372036854775807")
                                           : "18446744073709551615";
        if (digits.size() > most.size() || (digits.size() == most.size() && digits > most))
          return (negative ? "must be at least -" : "must be at most ") + most + ", not \"" + s + "\"";
        s = (negative ? "-" : "") + digits;
        return std::string();
      },
      "", "decimal");
}

}  // namespace

void refuse_outputs_over_inputs(CLI::App& app) {
  std::vector<NamedPath> inputs, outputs;
  collect(&app, inputs, outputs);
  for (const NamedPath& out : outputs)
    for (const NamedPath& in : inputs) refuse_output_over_input(out.option, out.path, in.option, in.path);
}

void protect_inputs(OutputFiles& out, const LoadedInput& in) {
  out.protect(in.path, "INPUT");
  for (const std::string& file : in.files) out.protect(file, "that INPUT refers to");
}

void read_integers_in_decimal(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    const bool is_signed = type.rfind("INT", 0) == 0, is_unsigned = type.rfind("UINT", 0) == 0;
    // transform, not check: it runs before the option's other checks, and its rewritten value is the one converted
    if (is_signed || is_unsigned) option->transform(decimal_whole_number(is_signed));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) read_integers_in_decimal(*sub);
}

void occupy_closed_standard_descriptors() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int stand_in = ::open("/dev/null", (fd == 0 ? O_WRONLY : O_RDONLY) | O_NOCTTY);
    if (stand_in < 0 || stand_in == fd) continue;  // open takes the lowest free number: normally `fd` itself
    ::dup2(stand_in, fd);
    ::close(stand_in);
  }
}

std::string standard_output_error() {
  std::cout.flush();
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0;
  const int error = errno;
  if (!flush_failed && !std::ferror(stdout) && std::cout) return "";
  return flush_failed && error != 0 ? std::strerror(error)
                                     : "a write to it failed (a full disk, a closed descriptor or pipe)";
}

}  // namespace hsx::cli
