// SPDX-License-Identifier: Apache-2.0
#include "CommandLine.h"

#include "Drop.h"
#include "ErrorExit.h"
#include "Generators.h"
#include "Interrupts.h"
#include "Notes.h"
#include "OptionTable.h"
#include "OutOfMemory.h"
#include "Suggest.h"
#include "Usage.h"
#include "Vocabulary.h"

#include "lut/io/MemoryLimit.h"

#include "lut/Error.h"
#include "lut/Version.h"
#include "lut/formats/ColorConfig.h"
#include "lut/formats/LibraryMessages.h"
#include "lut/formats/RequestError.h"
#include "lut/io/FileNames.h"
#include "lut/io/MemoryLimit.h"
#include "lut/io/TempFiles.h"
#include "lut/os/Console.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

namespace lut::cli {

namespace {

// The subcommand's callback: the hook (or the real run function) with its exit code kept, its
// report silenced by -q (Notes.h: the one place -q takes the report away).
template <class Options>
std::function<void(const Options&)> runner(const RunFn<Options>& hook, int (*real)(const Options&),
                                           int& exitCode) {
    RunFn<Options> run = hook ? hook : RunFn<Options>(real);
    return [run, &exitCode](const Options& o) {
        const QuietReport quiet(reportSilenced(o));
        exitCode = run(o);
    };
}

std::vector<std::string> commandNames(CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub :
         app.get_subcommands([](CLI::App* s) { return !s->get_group().empty(); }))
        names.push_back(sub->get_name());
    return names;
}

// The files a subcommand was given (its positional arguments), for messages that must name them.
std::string positionalFiles(const std::vector<CLI::App*>& parsed) {
    std::string files;
    if (parsed.empty())
        return files;
    for (const CLI::Option* o : parsed.front()->get_options())
        if (!o->nonpositional()) // a positional argument: a file name
            for (const auto& r : o->results())
                files += (files.empty() ? "" : ", ") + r;
    return files;
}

std::string joined(const std::vector<std::string>& words) {
    std::string s;
    for (std::size_t i = 0; i < words.size(); ++i)
        s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
    return s;
}

// What to say about an unknown option `--name` of sub (lutkit never abbreviates options): that it
// is ambiguous when it starts several long names or is one letter (`--v`: a short option takes
// one dash), else the option it is nearly; "" when nothing is close.
std::string unknownOptionAdvice(const CLI::App& sub, const std::string& name) {
    std::vector<std::string> longs, started;
    for (const CLI::Option* o : sub.get_options())
        for (const auto& n : o->get_lnames()) {
            if (o->get_group().empty()) // hidden: an old spelling
                continue;
            longs.push_back("--" + n);
            if (longs.back().rfind(name, 0) == 0)
                started.push_back(longs.back());
        }
    const std::string quoted = "'" + printable(name) + "'";
    if (name.size() == 3) { // --v
        const std::string shortName = "-" + name.substr(2);
        const CLI::Option* s = sub.get_option_no_throw(shortName);
        std::string msg =
            quoted + " is ambiguous: a short option takes one dash (" +
            (s ? shortName + " is " + s->get_name() : sub.get_name() + " has no " + shortName) +
            "), a long one is written in full";
        return msg + (started.empty() ? "" : " (" + joined(started) + ")");
    }
    if (started.size() > 1)
        return quoted + " is ambiguous: " + joined(started) + " (options are written in full)";
    if (const auto guess = closestWord(name, longs))
        return "did you mean '" + *guess + "'?";
    return {};
}

} // namespace

CommandLine::CommandLine(const RunHooks& hooks)
    : m_hooks(hooks), m_app("lutkit: author and convert colour grading LUTs", "lutkit") {
    // Options are -x and --xx everywhere: CLI11 would take "/x" for an option on Windows, and
    // "/mods/lut.png" is a path there too. Set first: subcommands inherit it.
    m_app.allow_windows_style_options(false);
    m_app.set_version_flag("-V,--version", std::string("lutkit ") + LUTKIT_VERSION,
                           "print the version and exit");
    m_app.set_help_flag("-h,--help", "print this help and exit");
    m_app.require_subcommand(0, 1);

    setupNeutral(m_app, runner(hooks.neutral, runNeutral, m_exitCode));
    setupConvert(m_app, runner(hooks.convert, runConvert, m_exitCode));
    setupInfo(m_app, runner(hooks.info, runInfo, m_exitCode));
    setupValidate(m_app, runner(hooks.validate, runValidate, m_exitCode));
    setupApply(m_app, runner(hooks.apply, runApply, m_exitCode));
    setupPreview(m_app, runner(hooks.preview, runPreview, m_exitCode));
    setupEmbed(m_app, runner(hooks.embed, runEmbed, m_exitCode));
    setupExtract(m_app, runner(hooks.extract, runExtract, m_exitCode));
    setupFit(m_app, runner(hooks.fit, runFit, m_exitCode));
    setupMatch(m_app, runner(hooks.match, runMatch, m_exitCode));
    setupBench(m_app, runner(hooks.bench, runBench, m_exitCode));
    setupBake(m_app, runner(hooks.bake, runBake, m_exitCode));
    setupDiff(m_app, runner(hooks.diff, runDiff, m_exitCode));
    setupCompose(m_app, runner(hooks.compose, runCompose, m_exitCode));
    setupInvert(m_app, runner(hooks.invert, runInvert, m_exitCode));
    setupResize(m_app, runner(hooks.resize, runResize, m_exitCode));
    setupSmooth(m_app, runner(hooks.smooth, runSmooth, m_exitCode));
    setupMix(m_app, runner(hooks.mix, runMix, m_exitCode));
    setupPlot(m_app, runner(hooks.plot, runPlot, m_exitCode));
    setupAdjust(m_app, runner(hooks.adjust, runAdjust, m_exitCode));
    setupCheck(m_app, runner(hooks.check, runCheck, m_exitCode));
    setupChart(m_app, runner(hooks.chart, runChart, m_exitCode));
    setupAtlas(m_app, runner(hooks.atlas, runAtlas, m_exitCode));

    // Every command takes --max-memory, with one default (lut/io/MemoryLimit.h); apply and
    // preview add theirs, which also bounds the files they run at once.
    for (CLI::App* sub : m_app.get_subcommands({}))
        if (!sub->get_option_no_throw("--max-memory"))
            addMaxMemory(*sub, m_maxMemory,
                         "the most memory the command may hold at once (a picture, standard "
                         "input): 4G, 512M (default: half the RAM)");
    refuseNonFiniteNumbers(m_app);

    const std::vector<std::string> commands = commandNames(m_app);
    auto* help = m_app.add_subcommand("help", "Show the help of lutkit or of one command");
    Choices topics{"command", "command", commands, {}, {}};
    topics.accept = [commands](const std::string& s) {
        // `help help` is help's own help (its error said "Run 'lutkit help help'": a loop).
        if (s != "help" && std::find(commands.begin(), commands.end(), s) == commands.end())
            throw Error("unknown command '" + s + "'");
    };
    help->add_option("COMMAND", m_helpTopic, "the command to explain")
        ->type_name("COMMAND")
        ->check(choicesValidator(topics));
    help->footer("Examples:\n  lutkit help\n  lutkit help convert");
    help->callback([this] { m_helpRequested = true; });

    m_app.add_option("--generate", m_generate, "print the man page or a shell completion script")
        ->check(CLI::IsMember(generatorKinds()))
        ->group("");
    // What the shell completions (Completions.cpp) offer after --from, --look, --display, --view:
    // the active config's names, one a line; nothing on standard output when there is no config.
    m_app.add_option("--names", m_names, "print the active config's names, one a line")
        ->type_name("KIND")
        ->group("");
    m_app.footer("Run 'lutkit help COMMAND' (or lutkit COMMAND --help) for a command's options "
                 "and examples.\nExit codes: 0 success, 1 bad input or failed operation, 2 bad "
                 "usage, 130 interrupted (Ctrl-C, SIGTERM; nothing half-written is left).");
}

int CommandLine::run(int argc, const char* const* argv) {
    os::prepareStandardStreams();      // bytes as they are (Windows: binary mode, UTF-8 console)
    installInterruptHandlers();        // the program's own run: Ctrl-C removes what is half-written
    formats::captureLibraryMessages(); // OpenColorIO logs nothing to the terminal
    int code = run(os::programArguments(argc, argv));
    // What went to standard output (reports, --json, lists) is output the user asked for: a
    // full disk or a closed pipe is a failed write like any other (`info --json > /dev/full`).
    errno = 0;
    std::cout.flush();
    const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
    if (failed) {
        const int err = errno;
        std::cerr << "lutkit: error: -: cannot write standard output"
                  << (err ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
        code = code == kExitOk ? kExitFailure : code;
    }
    // Started by a double click or a drop (Windows): the window would close with the report.
    if (os::consoleIsOwnWindow())
        os::waitForKey("\nPress a key to close this window.\n");
    return code;
}

int CommandLine::runDrop(const std::vector<std::string>& files) {
    int code = kExitOk;
    std::size_t written = 0;
    for (const std::string& in : files) {
        if (&in != &files.front())
            std::cout << "\n";
        const DropTarget t = dropTarget(in);
        if (!t.refused.empty()) {
            std::cout.flush();
            std::cerr << "lutkit: error: " << t.refused << "\n";
            code = std::max<int>(code, kExitFailure);
            continue;
        }
        std::cout << "lutkit: " << in << " -> " << t.output;
        if (t.output != t.usual)
            std::cout << " (" << t.usual << " is there already and is kept; rename the new one "
                      << "for the game)";
        std::cout << "\n";
        std::cout.flush();
        // Exactly `lutkit convert IN OUT`: its options, its checks, its report, its exit code.
        const int c = CommandLine(m_hooks).run(std::vector<std::string>{"convert", in, t.output});
        if (c == kExitInterrupted)
            return c;
        if (c == kExitOk)
            ++written;
        else
            code = std::max(code, c);
    }
    if (files.size() > 1)
        std::cout << "\nlutkit: " << written << " of " << files.size()
                  << " dropped files written as the game's LUT\n";
    return code;
}

std::optional<std::string>
CommandLine::unknownCommandMessage(const std::vector<std::string>& args) const {
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--generate" || a == "--names") {
            ++i; // its value
            continue;
        }
        if (a.empty() || a[0] == '-')
            continue;
        std::vector<std::string> names;
        for (const CLI::App* sub : m_app.get_subcommands({}))
            names.push_back(sub->get_name());
        if (std::find(names.begin(), names.end(), a) != names.end())
            return std::nullopt;
        std::string msg = "lutkit: unknown command '" + a + "'";
        if (os::exists(a)) // files with an option: not a drop (Drop.h)
            msg += " (files alone make color_grading_lut.nutexb beside each; with options: "
                   "lutkit convert FILE OUT [OPTIONS])";
        else if (a.find('.') != std::string::npos ||
                 a.find_first_of(os::pathSeparators()) != std::string::npos)
            msg += ", and no file of that name (lutkit FILE... makes color_grading_lut.nutexb "
                   "beside each LUT file named)";
        else if (const auto guess = closestWord(a, names))
            msg += "; did you mean '" + *guess + "'?";
        return msg + "\nRun 'lutkit help' for the list of commands.\n";
    }
    return std::nullopt;
}

std::string CommandLine::commandPrefix() const {
    const auto parsed = m_app.get_subcommands();
    return parsed.empty() ? "lutkit: " : "lutkit " + parsed.front()->get_name() + ": ";
}

int CommandLine::reportError(const std::exception& e) {
    const ErrorKind kind = errorKind(e);
    switch (kind) {
    case ErrorKind::Interrupted: // a write refused after SIGINT/SIGTERM (Interrupts.h)
        std::cerr << "lutkit: interrupted (" << signalName(interruptSignal())
                  << "); unfinished outputs removed\n";
        break;
    case ErrorKind::Usage:
        std::cerr << commandPrefix() << printable(e.what()) << "\n";
        // A name the config lacks: the closest it has.
        if (const auto* c = dynamic_cast<const formats::ColorOptionError*>(&e);
            c && !c->value().empty())
            if (const auto guess = closestWord(c->value(), c->known()))
                std::cerr << commandPrefix() << "did you mean '" << *guess << "'?\n";
        break;
    case ErrorKind::Input:
    case ErrorKind::Io:
    case ErrorKind::Other:
        std::cerr << "lutkit: error: " << printable(e.what()) << "\n";
        break;
    }
    return cli::exitCode(kind);
}

int CommandLine::parseErrorExit(const CLI::ParseError& e) {
    if (e.get_exit_code() == 0)
        return m_app.exit(e) == 0 ? kExitOk : kExitUsage; // --help, -V
    const auto parsed = m_app.get_subcommands();
    CLI::App* sub = parsed.empty() ? nullptr : parsed.front();
    std::string what = e.what();
    if (what.rfind(": ", 0) == 0)
        what.erase(0, 2); // hidden (moved) options have no name in CLI11's messages
    // A file named like an option (`info -zz.cube`): CLI11 takes it for one it does not know and
    // then says only that the file is missing ("IN is required").
    if (sub && dynamic_cast<const CLI::RequiredError*>(&e))
        for (const std::string& extra : sub->remaining())
            if (extra.size() > 1 && extra[0] == '-' && extra.rfind("--", 0) != 0) {
                std::cerr << commandPrefix() << printable(extra)
                          << ": no such option; a file whose name starts with '-' is ./" +
                                 printable(extra) + " (or put -- before it)\n"
                          << "Run 'lutkit help " << sub->get_name() << "' for usage.\n";
                return kExitUsage;
            }
    // An unknown long option makes CLI11 say only that a required one is missing when that
    // one was misspelt (`apply --lutt x.cube`: "--lut is required"): name the typo instead.
    if (sub && dynamic_cast<const CLI::RequiredError*>(&e))
        for (const std::string& extra : sub->remaining())
            if (extra.size() > 2 && extra.rfind("--", 0) == 0) {
                const std::string name = extra.substr(0, extra.find('='));
                std::cerr << commandPrefix() << printable(name) << ": no such option\n";
                std::cerr << commandPrefix() << unknownOptionAdvice(*sub, name) << "\n";
                std::cerr << "Run 'lutkit help " << sub->get_name() << "' for usage.\n";
                return kExitUsage;
            }
    std::cerr << commandPrefix() << printable(what) << "\n";
    // An option name that is nearly one the command has: say which, or that it is ambiguous.
    if (sub && dynamic_cast<const CLI::ExtrasError*>(&e))
        for (const std::string& extra : sub->remaining())
            if (extra.size() > 2 && extra.rfind("--", 0) == 0)
                if (const std::string advice =
                        unknownOptionAdvice(*sub, extra.substr(0, extra.find('=')));
                    !advice.empty())
                    std::cerr << commandPrefix() << advice << "\n";
    std::cerr << "Run 'lutkit help" << (sub ? " " + sub->get_name() : "") << "' for usage.\n";
    return kExitUsage;
}

int CommandLine::run(const std::vector<std::string>& args) {
    setMemoryLimit(0); // the default, unless this command line sets it
    {
        std::vector<std::string> names = commandNames(m_app);
        names.push_back("help");
        if (isDrop(args, names))
            return runDrop(args);
    }
    if (const auto msg = unknownCommandMessage(args)) {
        std::cerr << *msg;
        return kExitUsage;
    }
    std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 pops from the back
    try {
        m_app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        return parseErrorExit(e);
    } catch (const CLI::Error& e) { // CLI11 misused: a bug here
        std::cerr << "lutkit: internal error: " << e.what() << "\n";
        return kExitFailure;
    } catch (const std::bad_alloc&) {
        const std::string files = positionalFiles(m_app.get_subcommands());
        std::cerr << "lutkit: error: " << printable(files.empty() ? "" : files + ": ")
                  << outOfMemoryText() << "\n";
        return kExitFailure;
    } catch (const std::exception& e) { // the command's and the library's (ErrorExit.h)
        return reportError(e);
    }
    if (!m_generate.empty()) {
        std::cout << generate(describeProgram(m_app), m_generate);
        return kExitOk;
    }
    if (!m_names.empty()) {
        try {
            for (const auto& n : formats::configNames(m_names))
                std::cout << n << "\n";
        } catch (const Error& e) {
            return reportError(e);
        }
        return kExitOk;
    }
    if (m_helpRequested) {
        if (m_helpTopic.empty())
            std::cout << m_app.get_formatter()->make_help(&m_app, "lutkit",
                                                          CLI::AppFormatMode::Normal);
        else
            std::cout << m_app.get_subcommand(m_helpTopic)->help("lutkit");
        return kExitOk;
    }
    if (m_app.get_subcommands().empty()) {
        std::cerr << howToUse() << "\n";
        std::cerr << "lutkit: A subcommand is required: one of";
        for (const auto& n : commandNames(m_app))
            std::cerr << " " << n;
        std::cerr << "\nRun 'lutkit help' for what each does.\n";
        return kExitUsage;
    }
    return m_exitCode;
}

} // namespace lut::cli
