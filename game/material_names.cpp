#include "game/material_names.h"

#include <array>

namespace game {

namespace {

struct BlockMaterial {
    const char* name;
    double friction, restitution;
};
constexpr std::array<BlockMaterial, 3> kBlockMaterials{{
    {"wood", 0.6, 0.3},
    {"stone", 0.7, 0.1},
    {"steel", 0.4, 0.5},
}};

struct SurfaceAlias {
    const char* name;
    phys::MaterialId id;
};
constexpr std::array<SurfaceAlias, 2> kSurfaceAliases{{
    {"ground", phys::material::kEarth},
    {"steel", phys::material::kFloor},
}};

} // namespace

std::optional<phys::RigidMaterial> blockMaterialFromName(const std::string& name) {
    for (const auto& m : kBlockMaterials)
        if (name == m.name) {
            phys::RigidMaterial r;
            r.friction = m.friction;
            r.restitution = m.restitution;
            return r;
        }
    return std::nullopt;
}

std::string blockMaterialNames() {
    std::string out;
    for (const auto& m : kBlockMaterials) out += (out.empty() ? "" : ", ") + std::string(m.name);
    return out;
}

std::optional<phys::MaterialId> surfaceMaterialFromName(const phys::MaterialTable& table,
                                                        const std::string& name) {
    for (const auto& a : kSurfaceAliases)
        if (name == a.name) return a.id;
    return table.find(name);
}

std::string surfaceMaterialNames(const phys::MaterialTable& table) {
    std::string out;
    for (const auto& a : kSurfaceAliases) out += (out.empty() ? "" : ", ") + std::string(a.name);
    for (phys::MaterialId id = 0; id < table.size(); ++id) out += ", " + table[id].name;
    return out;
}

} // namespace game
