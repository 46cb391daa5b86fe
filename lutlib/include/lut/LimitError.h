// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which limit of lut/Limits.h an input went over, as data. The library's messages name a limit
// by its C++ constant ("... over the limit of 256 (lut::limits::kMax3DSize)", what lutkit
// prints); a front end that words it otherwise (the editor: what the limit means) asks the error
// for its limit and its text with other words in the name's place, never reading the text.
#include "lut/Error.h"

#include <string>
#include <string_view>

namespace lut {

enum class LimitId {
    Max3DSize,        // limits::kMax3DSize: points per axis of a 3D LUT
    Max1DSize,        // limits::kMax1DSize: entries of a 1D LUT
    MaxTextLineBytes, // limits::kMaxTextLineBytes: a line of a text LUT
    MaxLutFileBytes,  // limits::kMaxLutFileBytes: a LUT file
};

// The name messages give the limit: "lut::limits::kMax3DSize".
const char* limitName(LimitId id);

// What every error for a named limit carries, whichever member of the Error family it is (a
// .cube's size on its line is a ParseError, a file's size a LimitError): the limit, and what()
// in two parts around its name.
class LimitExceeded {
public:
    virtual ~LimitExceeded();
    LimitId limit() const { return m_limit; }
    // what() with `words` in place of the limit's name.
    std::string whatWith(std::string_view words) const;

protected:
    LimitExceeded(LimitId limit, std::string before, std::string after)
        : m_limit(limit), m_before(std::move(before)), m_after(std::move(after)) {}

private:
    LimitId m_limit;
    std::string m_before, m_after;
};

// A file refused before it is read for its size: "PATH: file is N bytes, over the limit of M
// bytes (lut::limits::kMaxLutFileBytes)".
class FileLimitError : public LimitError, public LimitExceeded {
public:
    FileLimitError(LimitId limit, const std::string& before, const std::string& after)
        : LimitError(before + limitName(limit) + after), LimitExceeded(limit, before, after) {}
};

// A limit on a line of a text file: a ParseError (path, line, column, offending text) whose
// message is `before`, the limit's name, `after`.
class LineLimitError : public ParseError, public LimitExceeded {
public:
    LineLimitError(const std::string& path, int line, int column, LimitId limit,
                   const std::string& before, const std::string& after, std::string offending = {});
};

} // namespace lut
