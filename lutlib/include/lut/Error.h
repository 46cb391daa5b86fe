// SPDX-License-Identifier: Apache-2.0
#pragma once
// Errors thrown by lutlib and formats. The library never prints and never exits: callers (CLI,
// GUI) decide how to show these. Non-fatal findings come back as Diagnostics in results.
#include <stdexcept>
#include <string>
#include <vector>

namespace lut {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A parse error with the place it happened. line and column are 1-based physical positions
// (0 = unknown). what() is the one-line form "path:line:col: message" and, when lineText is set,
// ends with " (found 'text')" naming the offending text.
class ParseError : public Error {
public:
    ParseError(std::string path, int line, int column, std::string message,
               std::string offending = {});
    const std::string& path() const { return m_path; }
    int line() const { return m_line; }
    int column() const { return m_column; }
    const std::string& message() const { return m_message; }
    const std::string& offending() const { return m_offending; }

private:
    std::string m_path;
    int m_line;
    int m_column;
    std::string m_message;
    std::string m_offending;
};

// A file refused before reading it fully because it asks for more than a limit allows.
class LimitError : public Error {
public:
    using Error::Error;
};

// The system failed a read or a write: a file that cannot be opened or read, a write, sync or
// rename refused (a full disk, no permission), a written file that does not read back as written.
// Not the file's content (ParseError, LimitError, Error) nor the request (bad usage:
// lut::formats::RequestError). lutkit exits 1 for it, as for bad input (cli/ErrorExit.h).
class IoError : public Error {
public:
    using Error::Error;
};

// What a note is, for a front end that treats one apart (never by its text).
enum class NoteId {
    None,           // a note like any other
    BloomNotUndone, // preview's undo of a screenshot: its bloom stays (the same for every picture)
};

struct Diagnostic {
    enum class Severity { Info, Warning, Error };
    Severity severity = Severity::Warning;
    std::string path;
    int line = 0; // 0 = not tied to a line
    int column = 0;
    std::string message;
    NoteId id = NoteId::None;
    std::string str() const; // "path:line:col: warning: message"
};

using Diagnostics = std::vector<Diagnostic>;

} // namespace lut
