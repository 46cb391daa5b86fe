// SPDX-License-Identifier: Apache-2.0
// The LUT formats only OpenColorIO reads or writes, in the portable editions (docs/portable.md):
// each is still known by its name and extension, so `lutkit convert look.cube look.3dl` says that
// this edition cannot write .3dl (and what it can), rather than that .3dl is unknown. .spi3d is
// lutkit's own, read and written in every edition (spi3d/Spi3dFormat.cpp).
#include "Formats.h"

#include "lut/Error.h"
#include "lut/formats/Edition.h"

namespace lut::formats {

namespace {

const char* const kInstead = "write .cube, a LUT image (.png), .nutexb or .spi3d";

class UnavailableFormat final : public Format {
public:
    UnavailableFormat(std::string name, std::vector<std::string> extensions, std::string what,
                      bool reads, std::vector<FormatAlias> aliases = {})
        : m_name(std::move(name)), m_extensions(std::move(extensions)), m_what(std::move(what)),
          m_reads(reads), m_aliases(std::move(aliases)) {}
    std::string name() const override { return m_name; }
    std::string description() const override {
        return m_what + " (not in " + editionName() + ": needs OpenColorIO)";
    }
    std::vector<std::string> extensions() const override { return m_extensions; }
    std::vector<FormatAlias> aliases() const override { return m_aliases; }
    bool canRead() const override { return m_reads; }
    bool canWrite() const override { return !m_reads; }
    // Refused before the file is opened, as from bytes.
    LutFile read(const std::string& path, const FormatOptions& options) const override {
        return readMemory({}, path, options);
    }
    LutFile readMemory(std::string_view, const std::string& name,
                       const FormatOptions&) const override {
        throw Error(name + ": " +
                    notInEdition("reading " + m_what, "OpenColorIO",
                                 "convert it to .cube with the Linux build or another program"));
    }
    std::string writeMemory(const LutFile&, const std::string& path, const FormatOptions&,
                            Diagnostics*) const override {
        throw Error(path + ": " + notInEdition("writing " + m_what, "OpenColorIO", kInstead));
    }

private:
    std::string m_name;
    std::vector<std::string> m_extensions;
    std::string m_what;
    bool m_reads;
    std::vector<FormatAlias> m_aliases;
};

} // namespace

std::unique_ptr<Format> makeOcioReadFormat() {
    return std::make_unique<UnavailableFormat>(
        "ocio",
        std::vector<std::string>{".3dl", ".cc",    ".ccc",   ".cdl",    ".clf", ".ctf",  ".csp",
                                 ".lut", ".icc",   ".icm",   ".pf",     ".itx", ".look", ".mga",
                                 ".m3d", ".spi1d", ".spi3d", ".spimtx", ".cub", ".vf"},
        "a LUT file OpenColorIO reads", true);
}

std::vector<std::unique_ptr<Format>> makeOcioBakeFormats() {
    std::vector<std::unique_ptr<Format>> v;
    const auto add = [&v](const char* name, const char* ext, const char* what,
                          std::vector<FormatAlias> aliases = {}) {
        v.push_back(std::make_unique<UnavailableFormat>(name, std::vector<std::string>{ext}, what,
                                                        false, std::move(aliases)));
    };
    add("flame", ".3dl", "Autodesk Flame .3dl", {{"3dl", "", ""}});
    add("lustre", ".3dl", "Autodesk Lustre .3dl");
    add("csp", ".csp", "Cinespace .csp", {{"cinespace", "", ""}});
    add("clf", ".clf", "Academy/ASC Common LUT Format .clf",
        {{"Academy/ASC Common LUT Format", "", ""}});
    add("ctf", ".ctf", "Autodesk Color Transform Format .ctf",
        {{"Color Transform Format", "", ""}});
    add("cub", ".cub", "Truelight .cub", {{"truelight", "", ""}});
    add("itx", ".itx", "Iridas .itx", {{"iridas_itx", "", ""}});
    add("houdini", ".lut", "Houdini .lut");
    return v;
}

} // namespace lut::formats
