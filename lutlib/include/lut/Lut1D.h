// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lut {

// A per-channel 1D table (a shaper): entry i is the output for the input
// domainMin + (domainMax - domainMin) * i / (N - 1), per channel. Linear interpolation between
// entries, clamped to the end entries outside the domain.
class Lut1D {
public:
    Lut1D() = default;
    explicit Lut1D(int size); // 2..65536 entries, zero; throws lut::Error otherwise
    static Lut1D identity(int size);

    int size() const { return static_cast<int>(m_entries.size()); }
    bool empty() const { return m_entries.empty(); }
    glm::vec3& operator[](int i) { return m_entries[static_cast<std::size_t>(i)]; }
    const glm::vec3& operator[](int i) const { return m_entries[static_cast<std::size_t>(i)]; }
    std::vector<glm::vec3>& entries() { return m_entries; }
    const std::vector<glm::vec3>& entries() const { return m_entries; }

    glm::vec3 domainMin() const { return m_domainMin; }
    glm::vec3 domainMax() const { return m_domainMax; }
    void setDomain(glm::vec3 min, glm::vec3 max); // throws unless min < max, finite

    const std::string& title() const { return m_title; }
    void setTitle(std::string t) { m_title = std::move(t); }

    // Apply to one colour. NaN channels map to the first entry; +-Inf clamp to the end entries.
    glm::vec3 apply(glm::vec3 in) const;

private:
    std::vector<glm::vec3> m_entries;
    glm::vec3 m_domainMin{0.0f};
    glm::vec3 m_domainMax{1.0f};
    std::string m_title;
};

} // namespace lut
