#pragma once
// OpenColorIO as the oracle in tests: a file's processor (optionally with a CCC id), evaluated
// directly at given inputs.
#include "TestSupport.h"

#include <OpenColorIO/OpenColorIO.h>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lut::test {

namespace OCIO = OCIO_NAMESPACE;

inline OCIO::ConstCPUProcessorRcPtr ocioFileProcessor(const std::string& path,
                                                      const std::string& cccid = {}) {
    OCIO::ClearAllCaches();
    auto ft = OCIO::FileTransform::Create();
    ft->setSrc(path.c_str());
    ft->setInterpolation(OCIO::INTERP_BEST);
    if (!cccid.empty())
        ft->setCCCId(cccid.c_str());
    return OCIO::Config::CreateRaw()->getProcessor(ft)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
}

inline glm::vec3 ocioEval(const OCIO::ConstCPUProcessorRcPtr& p, glm::vec3 v) {
    p->applyRGB(&v.x);
    return v;
}

// The corpus (tests/data/ocio/corpus, README.md there): every file but the licence and readme,
// with the CCC id the .ccc/.cdl files need.
struct CorpusFile {
    std::string name;
    std::string cccid;
};

inline std::vector<CorpusFile> ocioCorpus() {
    return {{"camera_to_aces.spimtx", ""},
            {"clf/cdl_all_styles.clf", ""},
            {"cdl_test1.cc", ""},
            {"cdl_test1.ccc", "cc0003"},
            {"cdl_test1.cdl", "cc0002"},
            {"cdl_test_ASC_SAT.cc", ""},
            {"crosstalk.3dl", ""},
            {"difficult_test1_v1.ctf", ""},
            {"discreet-3d-lut.3dl", ""},
            {"clf/exponent_all_styles.clf", ""},
            {"exposure_contrast_log.ctf", ""},
            {"fixed_function.ctf", ""},
            {"gamma_test1.ctf", ""},
            {"houdini.lut", ""},
            {"icc-test-1.icc", ""},
            {"icc-test-3.icm", ""},
            {"iridas_3d.itx", ""},
            {"clf/log_all_styles.clf", ""},
            {"logtolin_8to8.lut", ""},
            {"lut1d_1.spi1d", ""},
            {"clf/lut1d_example.clf", ""},
            {"lut1d_inv.ctf", ""},
            {"clf/lut1d_lut3d_lut1d.clf", ""},
            {"clf/lut3d_17x17x17_10i_12i.clf", ""},
            {"lut3d_arbitrary.csp", ""},
            {"clf/lut3d_bizarre.clf", ""},
            {"lut3d_bizarre.spi3d", ""},
            {"lut3d_example_Inv.ctf", ""},
            {"clf/matrix_3x4_example.clf", ""},
            {"clf/multiple_ops.clf", ""},
            {"nuke_3d.vf", ""},
            {"pandora_3d.m3d", ""},
            {"clf/range_test1_noclamp.clf", ""},
            {"resolve_1d3d.cube", ""},
            {"clf/illegal/unknown_elements.clf", ""},
            {"clf/xyz_to_rgb.clf", ""}};
}

inline std::string corpusPath(const std::string& name) {
    return dataPath("ocio/corpus/" + name);
}

} // namespace lut::test
