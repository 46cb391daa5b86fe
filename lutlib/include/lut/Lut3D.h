// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lut {

// A 3D lookup table of edge size N (2..256) with float RGB entries.
//
// Storage order: red fastest, then green, then blue, the order of .cube files:
//     index(r, g, b) = r + N * (g + N * b)
// entry(r, g, b) is the output for the input
//     domainMin + (domainMax - domainMin) * (r, g, b) / (N - 1).
class Lut3D {
public:
    Lut3D() = default;
    // A LUT of edge `size` with every entry zero. Throws lut::Error if size is out of range.
    explicit Lut3D(int size);

    // The neutral (identity) LUT: entry(r,g,b) = (r,g,b)/(N-1) over the domain [0,1].
    static Lut3D identity(int size);

    int size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    std::size_t entryCount() const { return m_entries.size(); }

    // The one index function: red fastest, then green, then blue.
    std::size_t index(int r, int g, int b) const {
        return static_cast<std::size_t>(r) +
               static_cast<std::size_t>(m_size) *
                   (static_cast<std::size_t>(g) + static_cast<std::size_t>(m_size) * b);
    }
    glm::vec3& at(int r, int g, int b) { return m_entries[index(r, g, b)]; }
    const glm::vec3& at(int r, int g, int b) const { return m_entries[index(r, g, b)]; }

    std::vector<glm::vec3>& entries() { return m_entries; }
    const std::vector<glm::vec3>& entries() const { return m_entries; }
    const float* data() const { return &m_entries[0].x; }
    float* data() { return &m_entries[0].x; }

    glm::vec3 domainMin() const { return m_domainMin; }
    glm::vec3 domainMax() const { return m_domainMax; }
    // Throws lut::Error unless min < max per channel and both are finite.
    void setDomain(glm::vec3 min, glm::vec3 max);
    bool hasDefaultDomain() const;

    const std::string& title() const { return m_title; }
    void setTitle(std::string t) { m_title = std::move(t); }
    // Comment lines kept from the source file (without the leading '#').
    const std::vector<std::string>& comments() const { return m_comments; }
    std::vector<std::string>& comments() { return m_comments; }

    // The input colour that lattice point (r,g,b) stands for.
    glm::vec3 latticeInput(int r, int g, int b) const;

    // Largest absolute difference of any entry from the identity over this LUT's domain.
    float maxDeviationFromIdentity() const;
    bool isIdentity(float tolerance = 1e-6f) const {
        return maxDeviationFromIdentity() <= tolerance;
    }
    // Smallest and largest entry value over all channels (NaN entries ignored).
    std::pair<float, float> valueRange() const;

private:
    int m_size = 0;
    std::vector<glm::vec3> m_entries;
    glm::vec3 m_domainMin{0.0f};
    glm::vec3 m_domainMax{1.0f};
    std::string m_title;
    std::vector<std::string> m_comments;
};

} // namespace lut
