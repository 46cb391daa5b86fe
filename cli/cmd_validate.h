#pragma once
#include <string>
#include <vector>

namespace lut::cli {

struct ValidateOptions {
    std::vector<std::string> inputs;
    bool strict = false; // report every departure from the Adobe 1.0 .cube spec
    std::string format;  // input format name ("" = from the extension)
};

// Parses each file and reports: "FILE: ok (adobe 3D, 33^3)" on stdout for a good file,
// "FILE:line:col: warning: ..." lines on stdout for departures (--strict) and notes, and
// "FILE:line:col: error: ..." on stderr for a file that does not parse. Exit 1 if any file has
// an error or (with --strict) any departure, 0 otherwise.
int runValidate(const ValidateOptions& options);

} // namespace lut::cli
