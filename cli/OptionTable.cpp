// SPDX-License-Identifier: Apache-2.0
#include "OptionTable.h"

#include <CLI/CLI.hpp>

namespace lut::cli {

namespace {

std::vector<std::string> dashed(const std::vector<std::string>& names, const char* dashes) {
    std::vector<std::string> out;
    for (const auto& n : names)
        out.push_back(dashes + n);
    return out;
}

// "{a,b,c}" -> {"a", "b", "c"} (the description CLI11 and Vocabulary.h give a set of names).
std::vector<std::string> setValues(const std::string& description) {
    std::vector<std::string> values;
    if (description.size() < 2 || description.front() != '{' || description.back() != '}')
        return values;
    std::string cur;
    for (std::size_t i = 1; i + 1 < description.size(); ++i) {
        if (description[i] == ',') {
            values.push_back(cur);
            cur.clear();
        } else {
            cur += description[i];
        }
    }
    values.push_back(cur);
    return values;
}

OptionEntry describeOption(CLI::Option& opt) {
    OptionEntry e;
    e.shortNames = dashed(opt.get_snames(), "-");
    e.longNames = dashed(opt.get_lnames(), "--");
    if (opt.get_positional())
        e.positional = opt.get_name(true);
    if (opt.get_type_size_max() > 0) {
        const std::string full = opt.get_type_name();
        e.valueName = full.substr(0, full.find(':'));
    }
    e.help = opt.get_description();
    e.required = opt.get_required();
    e.repeatable = opt.get_expected_max() > 1 || opt.get_type_size_max() > 1 ||
                   opt.get_multi_option_policy() == CLI::MultiOptionPolicy::TakeAll;
    e.hidden = opt.get_group().empty();
    for (int i = 0;; ++i) {
        const CLI::Validator* v = nullptr;
        try {
            v = opt.get_validator(i);
        } catch (const CLI::OptionNotFound&) {
            break;
        }
        e.validators.push_back(v->get_name());
        const auto values = setValues(v->get_description());
        if (!values.empty())
            e.values = values;
    }
    return e;
}

} // namespace

std::string OptionEntry::displayName() const {
    if (!positional.empty())
        return positional;
    std::string s;
    for (const auto& n : shortNames)
        s += (s.empty() ? "" : ", ") + n;
    for (const auto& n : longNames)
        s += (s.empty() ? "" : ", ") + n;
    return s;
}

ProgramEntry describeProgram(CLI::App& app) {
    ProgramEntry p;
    p.name = app.get_name();
    p.description = app.get_description();
    p.footer = app.get_footer();
    for (CLI::Option* o : app.get_options())
        p.options.push_back(describeOption(*o));
    for (CLI::App* sub : app.get_subcommands([](CLI::App* s) { return !s->get_group().empty(); })) {
        CommandEntry c;
        c.name = sub->get_name();
        c.description = sub->get_description();
        c.footer = sub->get_footer();
        for (CLI::Option* o : sub->get_options())
            c.options.push_back(describeOption(*o));
        p.commands.push_back(std::move(c));
    }
    return p;
}

std::vector<std::string> footerExamples(const std::string& footer) {
    std::vector<std::string> examples;
    std::size_t start = 0;
    while (start <= footer.size()) {
        std::size_t end = footer.find('\n', start);
        if (end == std::string::npos)
            end = footer.size();
        std::string line = footer.substr(start, end - start);
        if (line.rfind("  lutkit ", 0) == 0) {
            line = line.substr(2);
            if (const auto hash = line.find(" #"); hash != std::string::npos)
                line = line.substr(0, hash);
            while (!line.empty() && line.back() == ' ')
                line.pop_back();
            examples.push_back(line);
        }
        start = end + 1;
    }
    return examples;
}

} // namespace lut::cli
