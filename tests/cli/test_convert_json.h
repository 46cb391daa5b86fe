// SPDX-License-Identifier: Apache-2.0
#pragma once
// A minimal strict JSON parser for the CLI tests: it throws on anything that is not valid JSON,
// so parsing the output is itself a check of `--json`.
#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lut::test::json {

struct Value {
    enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<Value> array;
    std::map<std::string, Value> object;

    const Value& operator[](const std::string& key) const {
        const auto it = object.find(key);
        if (type != Type::Object || it == object.end())
            throw std::runtime_error("no key '" + key + "'");
        return it->second;
    }
    const Value& operator[](std::size_t i) const { return array.at(i); }
    bool has(const std::string& key) const { return object.count(key) != 0; }
    bool isNull() const { return type == Type::Null; }
};

class Parser {
public:
    explicit Parser(const std::string& text) : m_s(text) {}
    Value parse() {
        Value v = value();
        ws();
        if (m_i != m_s.size())
            fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("invalid JSON at " + std::to_string(m_i) + ": " + what);
    }
    void ws() {
        while (m_i < m_s.size() &&
               (m_s[m_i] == ' ' || m_s[m_i] == '\n' || m_s[m_i] == '\r' || m_s[m_i] == '\t'))
            ++m_i;
    }
    bool eat(char c) {
        ws();
        if (m_i < m_s.size() && m_s[m_i] == c) {
            ++m_i;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!eat(c))
            fail(std::string("expected '") + c + "'");
    }
    bool word(const char* w) {
        const std::string s(w);
        if (m_s.compare(m_i, s.size(), s) == 0) {
            m_i += s.size();
            return true;
        }
        return false;
    }
    std::string str() {
        expect('"');
        std::string out;
        while (true) {
            if (m_i >= m_s.size())
                fail("unterminated string");
            const unsigned char c = static_cast<unsigned char>(m_s[m_i++]);
            if (c == '"')
                return out;
            if (c < 0x20)
                fail("raw control character in string");
            if (c != '\\') {
                out += static_cast<char>(c);
                continue;
            }
            if (m_i >= m_s.size())
                fail("bad escape");
            const char e = m_s[m_i++];
            switch (e) {
            case '"':
                out += '"';
                break;
            case '\\':
                out += '\\';
                break;
            case '/':
                out += '/';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                if (m_i + 4 > m_s.size())
                    fail("bad \\u escape");
                const unsigned long cp = std::strtoul(m_s.substr(m_i, 4).c_str(), nullptr, 16);
                m_i += 4;
                if (cp >= 0x80)
                    fail("test parser handles only ASCII \\u escapes");
                out += static_cast<char>(cp);
                break;
            }
            default:
                fail("bad escape");
            }
        }
    }
    Value value() {
        ws();
        if (m_i >= m_s.size())
            fail("unexpected end");
        Value v;
        const char c = m_s[m_i];
        if (c == '{') {
            v.type = Value::Type::Object;
            ++m_i;
            if (eat('}'))
                return v;
            do {
                ws();
                std::string k = str();
                expect(':');
                v.object[k] = value();
            } while (eat(','));
            expect('}');
        } else if (c == '[') {
            v.type = Value::Type::Array;
            ++m_i;
            if (eat(']'))
                return v;
            do
                v.array.push_back(value());
            while (eat(','));
            expect(']');
        } else if (c == '"') {
            v.type = Value::Type::String;
            v.string = str();
        } else if (word("null")) {
        } else if (word("true")) {
            v.type = Value::Type::Bool;
            v.boolean = true;
        } else if (word("false")) {
            v.type = Value::Type::Bool;
        } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
            v.type = Value::Type::Number;
            const char* begin = m_s.c_str() + m_i;
            char* end = nullptr;
            v.number = std::strtod(begin, &end);
            if (end == begin)
                fail("bad number");
            m_i += static_cast<std::size_t>(end - begin);
        } else {
            fail(std::string("unexpected '") + c + "'");
        }
        return v;
    }

    const std::string& m_s;
    std::size_t m_i = 0;
};

inline Value parse(const std::string& text) {
    return Parser(text).parse();
}

} // namespace lut::test::json
