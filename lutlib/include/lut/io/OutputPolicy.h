// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one rule for every file lutkit writes (every subcommand that writes, through one call, so
// the rule cannot differ between them):
//  - "-" is standard output. A character device, FIFO or socket, and any path under /dev or /proc
//    (/dev/stdout, /dev/null, /proc/self/fd/1), is written in place: opened and written, never
//    replaced by renaming a file over it.
//  - A folder is never an output file ("OUT: is a folder"), and no folder is ever created for a
//    file output; the folder it goes in must exist.
//  - An existing regular file is replaced only when the caller says so (ExistingOutput::Replace;
//    lutkit's -y/--overwrite); Skip leaves it alone (-n/--no-clobber); Refuse throws
//    OutputExistsError, and the file's bytes stay as they were.
//  - An output is never one of the command's inputs: the same path, a symbolic link or a hard
//    link to it (checkNotSameFile on each input; "-" and "" are skipped). Standard output ("-")
//    that the shell pointed at an input (`-o - 1<> in.png`) is refused the same way (same device
//    and inode).
//  - No two outputs of one command are one file (CommandOutputs): `match SRC REF OUT.png
//    --report-image OUT.png` wrote the report over the LUT.
//  - A symbolic link to a regular file is written through: the file it names is replaced and the
//    link stays.
// Regular files are then written through a temporary sibling renamed into place
// (lut/io/OutputFile.h), so a failed write leaves the old file as it was.
#include "lut/Error.h"

#include <string>
#include <vector>

namespace lut {

enum class ExistingOutput { Refuse, Replace, Skip };

enum class OutputKind {
    NewFile,      // nothing there yet
    ExistingFile, // a regular file that will be replaced (ExistingOutput::Replace)
    Stdout,       // "-"
    Special,      // device, FIFO, socket, /dev/..., /proc/...: written in place
    Memory,       // bytes in memory (memoryOutput): no file at all
};

struct OutputTarget {
    std::string path;      // as the caller gave it (for messages)
    std::string writePath; // where the bytes go: path, or the file a symbolic link names
    OutputKind kind = OutputKind::NewFile;
    bool skip = false; // ExistingOutput::Skip and the file exists: write nothing
    // OutputKind::Memory: the caller's string, given the bytes when the output is committed
    // (left as it was when the write fails).
    std::string* memory = nullptr;
    bool inPlace() const { return kind == OutputKind::Stdout || kind == OutputKind::Special; }
};

// "OUT: already exists (not replaced)". Programs add how to allow it (lutkit names -y).
class OutputExistsError : public Error {
public:
    explicit OutputExistsError(const std::string& path);
    const std::string& path() const { return m_path; }

private:
    std::string m_path;
};

// Applies the rule to one output path; never creates, opens or changes anything. Throws
// OutputExistsError, or lut::Error naming the path ("is a folder", "folder DIR does not exist",
// "output is the same file as input IN"). A path found absent under a rule that never replaces
// (Refuse, Skip) is remembered as an exclusive output: lut::AtomicFile renames into it only if
// it is still absent, so a file another program created meanwhile (two `lutkit convert` runs
// writing one new file) is kept and the second writer fails naming it.
OutputTarget checkOutput(const std::string& path, ExistingOutput rule,
                         const std::vector<std::string>& inputs = {});

// The outputs of one command: each one checked by checkOutput and against the outputs claimed
// before it, so that no two are one file (the same path however spelled, a link to it, the same
// device and inode, or standard output twice). A program makes one per command (lutkit: one per
// run, cli/Outputs.cpp); the editor, which saves one file at a time, has none.
class CommandOutputs {
public:
    // checkOutput(path, rule, inputs), then lut::Error "OUT: is also another output of this
    // command (OTHER); name another file" when it is the same file as an output claimed before.
    OutputTarget claim(const std::string& path, ExistingOutput rule,
                       const std::vector<std::string>& inputs = {});

private:
    std::vector<std::string> m_claimed;
};

// An output whose bytes go to `bytes` in memory (Format::writeMemory, the editor's export
// preview): `name` stands for it in messages and its extension picks the format, as a path's
// would. It can seek like a regular file; nothing touches the file system.
OutputTarget memoryOutput(const std::string& name, std::string& bytes);

// Whether path was found absent by checkOutput under Refuse or Skip and not written since.
bool isExclusiveOutput(const std::string& path);
// Written (by AtomicFile): the path is an ordinary output again.
void forgetExclusiveOutput(const std::string& path);

// Whether path stands for standard input or output ("-").
inline bool isStdStream(const std::string& path) {
    return path == "-";
}

} // namespace lut
