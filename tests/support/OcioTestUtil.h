// SPDX-License-Identifier: Apache-2.0
#pragma once
// OpenColorIO as the oracle in tests: a file's processor (optionally with a CCC id), a table as
// OCIO's own Lut3DTransform, evaluated directly at given inputs. Written here, apart from the
// product's builder (formats/src/ocio/OcioLut3D.h), so that an oracle shares no code with what it
// checks.
#include "TestSupport.h"
#include "lut/Lut3D.h"

#include <OpenColorIO/OpenColorIO.h>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lut::test {

namespace OCIO = OCIO_NAMESPACE;

// The faithful (unoptimized) float CPU processor of a transform.
inline OCIO::ConstCPUProcessorRcPtr ocioCpuProcessor(const OCIO::ConstTransformRcPtr& t) {
    return OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
}

inline OCIO::ConstCPUProcessorRcPtr ocioFileProcessor(const std::string& path,
                                                      const std::string& cccid = {}) {
    OCIO::ClearAllCaches();
    auto ft = OCIO::FileTransform::Create();
    ft->setSrc(path.c_str());
    ft->setInterpolation(OCIO::INTERP_BEST);
    if (!cccid.empty())
        ft->setCCCId(cccid.c_str());
    return ocioCpuProcessor(ft);
}

// lut as an OCIO Lut3DTransform over [0,1] with the given interpolation. setValue takes the
// red, green and blue lattice indices explicitly, so OCIO's internal order (blue fastest) does not
// matter here.
inline OCIO::Lut3DTransformRcPtr ocioLut3DTransform(const Lut3D& lut, OCIO::Interpolation interp) {
    const int n = lut.size();
    auto t = OCIO::Lut3DTransform::Create(static_cast<unsigned long>(n));
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 e = lut.at(r, g, b);
                t->setValue(static_cast<unsigned long>(r), static_cast<unsigned long>(g),
                            static_cast<unsigned long>(b), e.r, e.g, e.b);
            }
    t->setInterpolation(interp);
    return t;
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
