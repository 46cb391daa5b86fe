// SPDX-License-Identifier: Apache-2.0
// Shell completion scripts for bash, zsh and fish, generated from the option tables: command
// names, option names, the fixed values of an option (layouts, formats, presets ...) and of a
// command's first argument (atlas build|split|info, chart NAME), files where a file or an output
// path (-o) is expected and folders where a folder is, and the names of the active OpenColorIO
// config after --from, --to, --look, --display, --view ...: the scripts ask `lutkit --names KIND`
// (CommandLine.h), with OCIO set to the --config/--iconfig given on the line.
#include "Generators.h"

#include <algorithm>
#include <sstream>

namespace lut::cli {

namespace {

enum class Value { None, Flag, Files, Dirs, Fixed, Names };

Value valueOf(const OptionEntry& o) {
    if (o.valueName.empty())
        return Value::Flag;
    if (!o.values.empty())
        return Value::Fixed;
    if (o.valueName == "FILE" || o.valueName == "PATH") // PATH: -o, a file or a folder
        return Value::Files;
    if (o.valueName == "DIR")
        return Value::Dirs;
    if (o.valueName == "SPACE" || o.valueName == "LOOKS" || o.valueName == "DISPLAY" ||
        o.valueName == "VIEW")
        return Value::Names;
    return Value::None; // numbers, free text
}

// The kind `lutkit --names` takes for an option of Value::Names.
std::string namesKind(const OptionEntry& o) {
    if (o.valueName == "LOOKS")
        return "looks";
    if (o.valueName == "DISPLAY")
        return "displays";
    if (o.valueName == "VIEW")
        return "views";
    return "spaces";
}

// The fixed values of a command's first argument (atlas's ACTION), or none.
std::vector<std::string> firstArgumentValues(const CommandEntry& c) {
    for (const auto& o : c.options)
        if (!o.positional.empty())
            return o.values;
    return {};
}

std::string joined(const std::vector<std::string>& words, const char* sep = " ") {
    std::string s;
    for (const auto& w : words)
        s += (s.empty() ? "" : sep) + w;
    return s;
}

std::vector<std::string> names(const OptionEntry& o) {
    std::vector<std::string> all = o.shortNames;
    all.insert(all.end(), o.longNames.begin(), o.longNames.end());
    return all;
}

// A help text without its "(default ...)" and "(also ...)" asides, for one-line descriptions.
std::string shortHelp(const std::string& help) {
    const auto cut = std::min(help.find(" (default"), help.find(" (also"));
    return cut == std::string::npos ? help : help.substr(0, cut);
}

// For single quotes in sh/zsh/fish: ' -> '\''.
std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::vector<std::string> commandNames(const ProgramEntry& p) {
    std::vector<std::string> n;
    for (const auto& c : p.commands)
        n.push_back(c.name);
    return n;
}

void bashOptions(std::ostringstream& os, const CommandEntry& c) {
    std::vector<std::string> words, takes;
    os << "            case \"$prev\" in\n";
    for (const auto& o : c.options) {
        if (!o.positional.empty())
            continue;
        const auto n = names(o);
        const Value v = valueOf(o);
        if (v != Value::Flag)
            takes.insert(takes.end(), n.begin(), n.end());
        if (o.hidden)
            continue;
        words.insert(words.end(), n.begin(), n.end());
        if (v == Value::Flag)
            continue;
        os << "                " << joined(n, "|") << ")\n                    ";
        if (v == Value::Fixed)
            os << "COMPREPLY=($(compgen -W " << quoted(joined(o.values)) << " -- \"$cur\"))";
        else if (v == Value::Files)
            os << "_lutkit_files";
        else if (v == Value::Dirs)
            os << "_lutkit_dirs";
        else if (v == Value::Names)
            os << "_lutkit_names " << namesKind(o);
        else
            os << "COMPREPLY=()";
        os << "\n                    return 0 ;;\n";
    }
    os << "            esac\n            opts=" << quoted(joined(words))
       << "\n            takes=" << quoted(joined(takes))
       << "\n            first=" << quoted(joined(firstArgumentValues(c))) << " ;;\n";
}

std::string zshEscape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        if (c == '[' || c == ']' || c == ':' || c == '\\')
            out += '\\';
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out;
}

std::string zshAction(const OptionEntry& o) {
    switch (valueOf(o)) {
    case Value::Fixed:
        return "(" + joined(o.values) + ")";
    case Value::Files:
        return "_files";
    case Value::Dirs:
        return "_files -/";
    case Value::Names:
        return "_lutkit_names " + namesKind(o);
    default:
        return " ";
    }
}

void zshOptions(std::ostringstream& os, const std::vector<OptionEntry>& options) {
    for (const auto& o : options) {
        if (o.hidden)
            continue;
        const std::string desc = zshEscape(shortHelp(o.help));
        if (!o.positional.empty()) {
            os << "        '"
               << (o.repeatable ? "*"
                   : o.required ? ""
                                : ":")
               << ":" << zshEscape(o.positional) << ":" << zshAction(o) << "' \\\n";
            continue;
        }
        const auto n = names(o);
        const bool flag = valueOf(o) == Value::Flag;
        std::string spec;
        for (const auto& name : n)
            spec += (spec.empty() ? "" : ",") + name + (flag ? "" : name.size() == 2 ? "+" : "=");
        const std::string exclusive = o.repeatable ? "*" : "(" + joined(n) + ")";
        os << "        '" << exclusive << "'" << (n.size() > 1 ? "{" + spec + "}" : spec) << "'["
           << desc << "]";
        if (!flag)
            os << ":" << zshEscape(o.valueName) << ":" << zshAction(o);
        os << "' \\\n";
    }
}

// bash: the active config's names of a kind (lutkit --names: spaces, looks, displays, views),
// the config being the line's --config/--iconfig, else $OCIO, else lutkit's own; a look list
// ("a, +b") has its last item completed; names with blanks come back escaped.
constexpr const char* kBashNames = R"SH(_lutkit_names() {
    local kind=$1 cfg="" display="" word prefix="" q w j
    local -a found
    for ((j = 1; j < COMP_CWORD; j++)); do
        case "${COMP_WORDS[j]}" in
            --config|--iconfig) cfg=${COMP_WORDS[j+1]} ;;
            --display) display=${COMP_WORDS[j+1]} ;;
        esac
    done
    cfg=${cfg//[\\\"\']/}; cfg=${cfg/#\~/$HOME}
    display=${display//[\\\"\']/}
    [[ $kind == views && -n $display ]] && kind="views:$display"
    if [[ -n $cfg ]]; then
        mapfile -t found < <(OCIO="$cfg" "${COMP_WORDS[0]}" --names "$kind" 2>/dev/null)
    else
        mapfile -t found < <("${COMP_WORDS[0]}" --names "$kind" 2>/dev/null)
    fi
    word=${cur//[\\\"\']/}
    if [[ $kind == looks ]]; then
        if [[ $word == *,* ]]; then
            prefix="${word%,*},"; word=${word##*,}
        fi
        w=${word%%[!\ +-]*}; prefix+=$w; word=${word#"$w"}
    fi
    COMPREPLY=()
    for w in "${found[@]}"; do
        [[ $w == "$word"* ]] || continue
        printf -v q %q "$prefix$w"
        COMPREPLY+=("$q")
    done
}
)SH";

// zsh: the same, through compadd (which quotes what it inserts).
constexpr const char* kZshNames = R"SH(_lutkit_names() {
    local kind=$1 cfg= i
    local -a found
    i=${words[(I)--config]}
    (( i )) || i=${words[(I)--iconfig]}
    (( i )) && cfg=${(Q)words[i+1]}
    cfg=${cfg/#\~/$HOME}
    i=${words[(I)--display]}
    [[ $kind == views ]] && (( i )) && kind="views:${(Q)words[i+1]}"
    if [[ -n $cfg ]]; then
        found=(${(f)"$(OCIO=$cfg $_lutkit_prog --names $kind 2>/dev/null)"})
    else
        found=(${(f)"$($_lutkit_prog --names $kind 2>/dev/null)"})
    fi
    if [[ $kind == looks ]]; then
        compset -P '*,'
        compset -P '[ +-]##'
    fi
    compadd -a found
}
)SH";

// fish: the same, from the command line's tokens.
constexpr const char* kFishNames = R"SH(function __lutkit_names
    set -l kind $argv[1]
    set -l words (commandline -opc)
    set -l cfg
    set -l display
    set -l n (count $words)
    for i in (seq $n)
        if test $i -lt $n
            switch $words[$i]
                case --config --iconfig
                    set cfg $words[(math $i + 1)]
                case --display
                    set display $words[(math $i + 1)]
            end
        end
    end
    if test "$kind" = views; and test -n "$display"
        set kind views:$display
    end
    if test -n "$cfg"
        env OCIO=$cfg $words[1] --names $kind 2>/dev/null
    else
        $words[1] --names $kind 2>/dev/null
    end
end
)SH";

} // namespace

std::string bashCompletion(const ProgramEntry& p) {
    std::ostringstream os;
    os << "# bash completion for lutkit. Generated by lutkit --generate bash from its option "
          "tables; do not edit.\n"
          "_lutkit_files() {\n"
          "    compopt -o filenames 2>/dev/null\n"
          "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
          "}\n"
          "_lutkit_dirs() {\n"
          "    compopt -o filenames 2>/dev/null\n"
          "    COMPREPLY=($(compgen -d -- \"$cur\"))\n"
          "}\n"
       << kBashNames
       << "_lutkit() {\n"
          "    local cur prev cmd opts takes first i j n\n"
          "    cur=\"${COMP_WORDS[COMP_CWORD]}\"\n"
          "    prev=\"\"\n"
          "    (( COMP_CWORD > 0 )) && prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
          "    # --opt=value: bash splits the word at '='.\n"
          "    if [[ $cur == = ]]; then\n"
          "        prev=\"${COMP_WORDS[COMP_CWORD-1]}\"; cur=\"\"\n"
          "    elif [[ $prev == = ]] && (( COMP_CWORD > 1 )); then\n"
          "        prev=\"${COMP_WORDS[COMP_CWORD-2]}\"\n"
          "    fi\n"
          "    cmd=\"\"\n"
          "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
          "        case \"${COMP_WORDS[i]}\" in\n"
          "            -*) ;;\n"
          "            *) cmd=\"${COMP_WORDS[i]}\"; break ;;\n"
          "        esac\n"
          "    done\n"
          "    case \"$cmd\" in\n"
          "        \"\")\n";
    std::vector<std::string> top;
    for (const auto& o : p.options)
        if (!o.hidden) {
            const auto n = names(o);
            top.insert(top.end(), n.begin(), n.end());
        }
    os << "            if [[ \"$cur\" == -* ]]; then\n"
          "                COMPREPLY=($(compgen -W "
       << quoted(joined(top))
       << " -- \"$cur\"))\n"
          "            else\n"
          "                COMPREPLY=($(compgen -W "
       << quoted(joined(commandNames(p)))
       << " -- \"$cur\"))\n"
          "            fi\n"
          "            return 0 ;;\n";
    for (const auto& c : p.commands) {
        os << "        " << c.name << ")\n";
        bashOptions(os, c);
    }
    os << "        *) return 0 ;;\n"
          "    esac\n"
          "    if [[ \"$cur\" == -* ]]; then\n"
          "        COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
          "    elif [[ \"$cmd\" == help ]]; then\n"
          "        COMPREPLY=($(compgen -W "
       << quoted(joined(commandNames(p)))
       << " -- \"$cur\"))\n"
          "    else\n"
          "        # The command's arguments before this one (option values skipped): its first\n"
          "        # may be one of a fixed set (atlas build|split|info).\n"
          "        n=0\n"
          "        for ((j = i + 1; j < COMP_CWORD; j++)); do\n"
          "            case \"${COMP_WORDS[j]}\" in\n"
          "                -*) if [[ \" $takes \" == *\" ${COMP_WORDS[j]} \"* ]]; then\n"
          "                        ((j++)); [[ ${COMP_WORDS[j]} == = ]] && ((j++))\n"
          "                    fi ;;\n"
          "                =) ;;\n"
          "                *) ((n++)) ;;\n"
          "            esac\n"
          "        done\n"
          "        if [[ -n $first ]] && (( n == 0 )); then\n"
          "            COMPREPLY=($(compgen -W \"$first\" -- \"$cur\"))\n"
          "        else\n"
          "            _lutkit_files\n"
          "        fi\n"
          "    fi\n"
          "    return 0\n"
          "}\n"
          "complete -F _lutkit lutkit\n";
    return os.str();
}

std::string zshCompletion(const ProgramEntry& p) {
    std::ostringstream os;
    os << "#compdef lutkit\n"
          "# zsh completion for lutkit. Generated by lutkit --generate zsh from its option "
          "tables; do not edit.\n"
       << kZshNames
       << "_lutkit() {\n"
          "    local curcontext=\"$curcontext\" state line\n"
          "    local _lutkit_prog=${words[1]/#\\~/$HOME}\n"
          "    typeset -A opt_args\n"
          "    local -a commands\n"
          "    commands=(\n";
    for (const auto& c : p.commands)
        os << "        '" << c.name << ":" << zshEscape(shortHelp(c.description)) << "'\n";
    os << "    )\n"
          "    _arguments -C \\\n";
    zshOptions(os, p.options);
    os << "        '1:command:->command' \\\n"
          "        '*::arg:->args'\n"
          "    case $state in\n"
          "    command)\n"
          "        _describe -t commands 'lutkit command' commands ;;\n"
          "    args)\n"
          "        case $words[1] in\n";
    for (const auto& c : p.commands) {
        os << "        " << c.name << ")\n"
           << "            _arguments \\\n";
        zshOptions(os, c.options);
        os << "            && return 0 ;;\n";
    }
    os << "        esac ;;\n"
          "    esac\n"
          "}\n"
          "_lutkit \"$@\"\n";
    return os.str();
}

std::string fishCompletion(const ProgramEntry& p) {
    std::ostringstream os;
    os << "# fish completion for lutkit. Generated by lutkit --generate fish from its option "
          "tables; do not edit.\n"
          "complete -c lutkit -f\n"
       << kFishNames;
    const std::string commands = joined(commandNames(p));
    for (const auto& c : p.commands)
        os << "complete -c lutkit -n " << quoted("not __fish_seen_subcommand_from " + commands)
           << " -a " << c.name << " -d " << quoted(shortHelp(c.description)) << "\n";
    for (const auto& o : p.options) {
        if (o.hidden)
            continue;
        os << "complete -c lutkit -n __fish_use_subcommand";
        for (const auto& s : o.shortNames)
            os << " -s " << s.substr(1);
        for (const auto& l : o.longNames)
            os << " -l " << l.substr(2);
        os << " -d " << quoted(shortHelp(o.help)) << "\n";
    }
    for (const auto& c : p.commands) {
        const std::string when = quoted("__fish_seen_subcommand_from " + c.name);
        bool files = false;
        for (const auto& o : c.options) {
            if (o.hidden)
                continue;
            const Value v = valueOf(o);
            if (!o.positional.empty()) {
                files = files || v == Value::Files || v == Value::Dirs;
                // The first argument's fixed values (atlas build|split|info), until one is given.
                if (v == Value::Fixed)
                    os << "complete -c lutkit -n "
                       << quoted("__fish_seen_subcommand_from " + c.name +
                                 "; and not __fish_seen_subcommand_from " + joined(o.values))
                       << " -a " << quoted(joined(o.values)) << "\n";
                continue;
            }
            os << "complete -c lutkit -n " << when;
            for (const auto& s : o.shortNames)
                os << " -s " << s.substr(1);
            for (const auto& l : o.longNames)
                os << " -l " << l.substr(2);
            if (v == Value::Fixed)
                os << " -x -a " << quoted(joined(o.values));
            else if (v == Value::Files)
                os << " -r -F";
            else if (v == Value::Dirs)
                os << " -x -a '(__fish_complete_directories)'";
            else if (v == Value::Names)
                os << " -x -a " << quoted("(__lutkit_names " + namesKind(o) + ")");
            else if (v != Value::Flag)
                os << " -x";
            os << " -d " << quoted(shortHelp(o.help)) << "\n";
        }
        if (files)
            os << "complete -c lutkit -n " << when << " -F\n";
    }
    return os.str();
}

} // namespace lut::cli
