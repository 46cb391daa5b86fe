// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioConfigChecks.h"

#include "ocio/OcioInputChecks.h"

#include <functional>
#include <map>
#include <set>
#include <vector>

namespace lut::formats {

namespace {

// A node of the reference graph: "colour space NAME", "look NAME", "view transform NAME",
// "named transform NAME".
using Node = std::string;

class ConfigWalk {
public:
    ConfigWalk(const OCIO::ConstConfigRcPtr& config, std::string path)
        : m_config(config), m_path(std::move(path)) {}

    void run() {
        using OCIO::COLORSPACE_ALL;
        using OCIO::SEARCH_REFERENCE_SPACE_ALL;
        for (int i = 0; i < m_config->getNumColorSpaces(SEARCH_REFERENCE_SPACE_ALL, COLORSPACE_ALL);
             ++i) {
            const char* name =
                m_config->getColorSpaceNameByIndex(SEARCH_REFERENCE_SPACE_ALL, COLORSPACE_ALL, i);
            const auto cs = m_config->getColorSpace(name);
            if (!cs)
                continue;
            const Node node = "colour space '" + std::string(cs->getName()) + "'";
            m_nodes.insert(node);
            walk(node, cs->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE));
            walk(node, cs->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE));
        }
        for (int i = 0; i < m_config->getNumLooks(); ++i) {
            const char* name = m_config->getLookNameByIndex(i);
            const auto look = m_config->getLook(name);
            if (!look)
                continue;
            const Node node = "look '" + std::string(look->getName()) + "'";
            m_nodes.insert(node);
            addColorSpace(node, look->getProcessSpace());
            walk(node, look->getTransform());
            walk(node, look->getInverseTransform());
        }
        for (int i = 0; i < m_config->getNumViewTransforms(); ++i) {
            const char* name = m_config->getViewTransformNameByIndex(i);
            const auto vt = m_config->getViewTransform(name);
            if (!vt)
                continue;
            const Node node = "view transform '" + std::string(vt->getName()) + "'";
            m_nodes.insert(node);
            walk(node, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE));
            walk(node, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE));
        }
        for (int i = 0; i < m_config->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i) {
            const char* name = m_config->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
            const auto nt = m_config->getNamedTransform(name);
            if (!nt)
                continue;
            const Node node = "named transform '" + std::string(nt->getName()) + "'";
            m_nodes.insert(node);
            walk(node, nt->getTransform(OCIO::TRANSFORM_DIR_FORWARD));
            walk(node, nt->getTransform(OCIO::TRANSFORM_DIR_INVERSE));
        }
        findCycle();
    }

private:
    void addColorSpace(const Node& from, const char* name) {
        if (!name || !*name)
            return;
        if (const auto cs = m_config->getColorSpace(name)) // roles and aliases too
            m_edges[from].insert("colour space '" + std::string(cs->getName()) + "'");
    }

    void addLooks(const Node& from, const char* looks) {
        if (!looks)
            return;
        std::string token;
        const std::string text = std::string(looks) + ",";
        for (char c : text) {
            if (c == ',' || c == ':' || c == '|') {
                const auto b = token.find_first_not_of(" \t+-");
                const auto e = token.find_last_not_of(" \t");
                if (b != std::string::npos && e >= b)
                    if (const auto look = m_config->getLook(token.substr(b, e - b + 1).c_str()))
                        m_edges[from].insert("look '" + std::string(look->getName()) + "'");
                token.clear();
            } else {
                token += c;
            }
        }
    }

    void walk(const Node& node, const OCIO::ConstTransformRcPtr& t, int depth = 0) {
        if (!t || depth > 64)
            return;
        if (const auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t)) {
            for (int i = 0; i < g->getNumTransforms(); ++i)
                walk(node, g->getTransform(i), depth + 1);
        } else if (const auto f = OCIO::DynamicPtrCast<const OCIO::FileTransform>(t)) {
            checkFile(node, f->getSrc());
        } else if (const auto c = OCIO::DynamicPtrCast<const OCIO::ColorSpaceTransform>(t)) {
            addColorSpace(node, c->getSrc());
            addColorSpace(node, c->getDst());
        } else if (const auto l = OCIO::DynamicPtrCast<const OCIO::LookTransform>(t)) {
            addColorSpace(node, l->getSrc());
            addColorSpace(node, l->getDst());
            addLooks(node, l->getLooks());
        } else if (const auto d = OCIO::DynamicPtrCast<const OCIO::DisplayViewTransform>(t)) {
            addColorSpace(node, d->getSrc());
            const char* display = d->getDisplay();
            const char* view = d->getView();
            if (display && view) {
                addColorSpace(node, m_config->getDisplayViewColorSpaceName(display, view));
                addLooks(node, m_config->getDisplayViewLooks(display, view));
                const char* vt = m_config->getDisplayViewTransformName(display, view);
                if (vt && *vt && m_config->getViewTransform(vt))
                    m_edges[node].insert("view transform '" + std::string(vt) + "'");
            }
        }
    }

    // The file OCIO would open, resolved as OCIO resolves it; one it cannot find is left to
    // OCIO's own message when the transform is used.
    void checkFile(const Node& node, const char* src) {
        if (!src || !*src)
            return;
        std::string resolved;
        try {
            resolved = m_config->getCurrentContext()->resolveFileLocation(src);
        } catch (const std::exception&) {
            return;
        }
        if (!m_files.insert(resolved).second)
            return;
        try {
            checkOcioFile(resolved);
        } catch (const Error& e) {
            throw Error(m_path + ": " + node + " reads " + src + ": " + e.what());
        }
    }

    void findCycle() {
        std::map<Node, int> state; // 0 unseen, 1 on the path, 2 done
        std::vector<Node> path;
        std::function<void(const Node&)> visit = [&](const Node& n) {
            state[n] = 1;
            path.push_back(n);
            for (const Node& next : m_edges[n]) {
                if (state[next] == 1) {
                    std::string cycle;
                    bool on = false;
                    for (const Node& p : path) {
                        on = on || p == next;
                        if (on)
                            cycle += p + " -> ";
                    }
                    throw Error(m_path + ": " + cycle + next +
                                ": these transforms refer to each other in a cycle (OpenColorIO "
                                "would follow them without end)");
                }
                if (state[next] == 0)
                    visit(next);
            }
            path.pop_back();
            state[n] = 2;
        };
        for (const Node& n : m_nodes)
            if (state[n] == 0)
                visit(n);
    }

    OCIO::ConstConfigRcPtr m_config;
    std::string m_path;
    std::set<Node> m_nodes;
    std::map<Node, std::set<Node>> m_edges;
    std::set<std::string> m_files;
};

} // namespace

void checkOcioConfig(const OCIO::ConstConfigRcPtr& config, const std::string& configPath) {
    ConfigWalk(config, configPath).run();
}

} // namespace lut::formats
