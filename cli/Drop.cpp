// SPDX-License-Identifier: Apache-2.0
#include "Drop.h"

#include "lut/Version.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Nutexb.h"
#include "lut/io/FileNames.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <algorithm>

namespace lut::cli {

bool isDrop(const std::vector<std::string>& args, const std::vector<std::string>& commands) {
    if (args.empty() || std::find(commands.begin(), commands.end(), args[0]) != commands.end())
        return false;
    for (const std::string& a : args)
        if (a.empty() || a[0] == '-')
            return false;
    os::FileInfo info;
    return os::fileInfo(args[0], info) == 0 && info.type != os::FileType::Directory;
}

DropTarget dropTarget(const std::string& input) {
    DropTarget t;
    if (formats::isGameFormatPath(input)) { // the library's rule (lut/formats/LutDestination.h)
        t.refused = input + ": is a game LUT (.nutexb) already; drop the edited strip or .cube " +
                    "it came from (lutkit info " + input + " says what it holds)";
        return t;
    }
    const std::string name = std::string(formats::nutexb::kDefaultName) + ".nutexb";
    const auto folder = os::toPath(input).parent_path();
    t.usual = folder.empty() ? name : os::fromPath(folder / os::toPath(name));
    t.output = firstFreeName(t.usual);
    return t;
}

std::string howToUse() {
    return std::string("lutkit ") + LUTKIT_VERSION +
           ": author and convert colour grading LUTs.\n"
           "\n"
           "Smash Ultimate: grade neutral.png (a 256x16 strip: lutkit neutral neutral.png) in\n"
           "your image editor, then drop it on lutkit (lutkit.exe on Windows), or run\n"
           "`lutkit graded.png`: color_grading_lut.nutexb appears beside it, the game's LUT.\n"
           "A .cube works the same; an existing .nutexb is kept (a new name is taken).\n"
           "\n"
           "From a terminal: lutkit COMMAND [OPTIONS] FILES...\n";
}

} // namespace lut::cli
