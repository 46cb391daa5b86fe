// SPDX-License-Identifier: Apache-2.0
#include "lut/Progress.h"

#include <algorithm>
#include <cmath>

namespace lut {

void Progress::report(double fraction) const {
    if (std::isnan(fraction))
        return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (m_parent)
        m_parent->report(m_from + fraction * (m_to - m_from));
    else if (m_callback)
        m_callback(fraction);
}

void Progress::check(const std::string& what) const {
    if (cancelled())
        throw CancelledError(what + ": cancelled");
}

} // namespace lut
