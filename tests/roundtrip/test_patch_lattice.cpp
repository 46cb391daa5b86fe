// SPDX-License-Identifier: Apache-2.0
// The patch lattice's user-facing names: "game-display" (alias "smash") and "uniform".
#include "lut/Error.h"
#include "lut/roundtrip/Extract.h"
#include "lut/roundtrip/PatchLattice.h"

#include <gtest/gtest.h>

#include <string>

using namespace lut;

TEST(PatchLatticeNames, GameDisplayIsTheNameAndSmashItsAlias) {
    EXPECT_EQ(parseLattice("game-display"), PatchLattice::Smash);
    EXPECT_EQ(parseLattice("smash"), PatchLattice::Smash);
    EXPECT_EQ(parseLattice("uniform"), PatchLattice::Uniform);
    EXPECT_STREQ(toString(PatchLattice::Smash), "game-display");
    EXPECT_STREQ(toString(PatchLattice::Uniform), "uniform");
}

TEST(PatchLatticeNames, UnknownNameIsRefusedWithTheAcceptedNames) {
    for (const char* bad : {"", "Smash", "game_display", "gamedisplay", "uniform "}) {
        try {
            parseLattice(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("game-display"), std::string::npos) << m;
            EXPECT_NE(m.find("uniform"), std::string::npos) << m;
        }
    }
}

TEST(PatchLatticeNames, ExtractTargetsKeepTheirNames) {
    // The target is the game ("smash"), not the lattice: it keeps its name.
    EXPECT_EQ(parseLutPurpose("smash"), LutPurpose::Smash);
    EXPECT_EQ(parseLutPurpose("raw"), LutPurpose::Raw);
    EXPECT_STREQ(toString(LutPurpose::Smash), "smash");
}
