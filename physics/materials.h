// Materials: what a surface is made of, and the restitution and friction of a PAIR.
//
// Restitution belongs to a pair of materials (Claypool, "Game Physics": e = sqrt(h/H) is measured by
// dropping a ball on a floor, so it describes ball AND floor). Each material stores
// its coefficient of restitution against the reference floor it was measured on,
// so against "floor" (e = 1, the rigid reference) a ball bounces with its own
// measured value.
//
// Combine rule for a pair with no entry of its own (documented in README.md):
//   e(A, B)  = e_A * e_B               each body returns the fraction e of the normal
//                                      relative speed it would against the rigid
//                                      reference; 0 (plastic) wins, 1 (elastic) is
//                                      neutral, e(ball, floor) = e_ball.
//   mu(A, B) = sqrt(mu_A * mu_B)       geometric mean, for static and dynamic friction
//                                      alike (as Box2D mixes friction).
// A pair entry (setPair) overrides the rule for that pair in both orders.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace phys {

using MaterialId = std::uint16_t;

struct Material {
    std::string name;
    double restitution = 0.5;     ///< e against the reference floor, 0..1
    double staticFriction = 0.5;  ///< mu_s, >= 0: tangential impulse that sticks
    double dynamicFriction = 0.4; ///< mu_d, 0..mu_s: tangential impulse while sliding
};

/// What a contact between two materials uses.
struct PairProperties {
    double restitution = 0.5;     ///< e, 0..1
    double staticFriction = 0.5;  ///< mu_s
    double dynamicFriction = 0.4; ///< mu_d
};

/// The material table. Built-in entries are always present with fixed ids (below), so
/// ParticleDef::material = 0 means "default".
class MaterialTable {
  public:
    MaterialTable();

    /// Adds a material; returns its id, or nullopt if the name is taken or a value is
    /// out of range (see validate()).
    std::optional<MaterialId> add(const Material& m);
    /// Overrides the combine rule for the pair (a, b), in both orders.
    void setPair(MaterialId a, MaterialId b, const PairProperties& p);
    /// Gives the pair (a, b) back to the combine rule.
    void clearPair(MaterialId a, MaterialId b);
    /// Changes a material's restitution against the reference floor (0..1); every pair
    /// without an entry of its own follows from the next contact on. False (and no
    /// change) when the id or the value is out of range.
    bool setRestitution(MaterialId id, double e);

    /// The pair's properties: its entry if it has one, else the combine rule. O(1).
    const PairProperties& pair(MaterialId a, MaterialId b) const {
        return mixed_[static_cast<std::size_t>(a) * materials_.size() + b];
    }
    std::optional<MaterialId> find(std::string_view name) const;
    const Material& operator[](MaterialId id) const { return materials_[id]; }
    std::size_t size() const { return materials_.size(); }
    /// "golf, tennis, ..." for messages and --help.
    std::string nameList() const;

    /// The combine rule itself (see the file comment).
    static PairProperties combine(const Material& a, const Material& b);

    /// A pair with an entry of its own (setPair), in the order it was first set.
    struct Override {
        MaterialId a, b;
        PairProperties p;
    };
    const std::vector<Override>& overrides() const { return overrides_; }
    /// The pair's own entry, if it has one (either order).
    const PairProperties* pairOverride(MaterialId a, MaterialId b) const;

  private:
    void rebuild();
    std::vector<Material> materials_;
    std::vector<Override> overrides_;
    std::vector<PairProperties> mixed_; // size^2, row-major
};

/// "" when the material is usable, else what is wrong.
std::string validate(const Material& m);

/// Ids of the built-in materials (the order of MaterialTable's constructor).
namespace material {
inline constexpr MaterialId kDefault = 0;
inline constexpr MaterialId kFloor = 1;
inline constexpr MaterialId kPerfectlyElastic = 2;
inline constexpr MaterialId kPerfectlyPlastic = 3;
inline constexpr MaterialId kGolf = 4;
inline constexpr MaterialId kTennis = 5;
inline constexpr MaterialId kBilliard = 6;
inline constexpr MaterialId kHandBall = 7;
inline constexpr MaterialId kWooden = 8;
inline constexpr MaterialId kSteelBearing = 9;
inline constexpr MaterialId kGlassMarble = 10;
inline constexpr MaterialId kRubberBandBall = 11;
inline constexpr MaterialId kHollowHardPlastic = 12;
inline constexpr MaterialId kBaseball = 13;
inline constexpr MaterialId kEarth = 14;
} // namespace material

/// The measured restitution presets (Claypool, "Game Physics": balls dropped from 92 cm
/// on a floor),
/// plus "perfectly elastic" and "perfectly plastic": the ids a player picks from.
struct RestitutionPreset {
    MaterialId id;
    const char* name;
    double restitution;
};
extern const RestitutionPreset kRestitutionPresets[11];

} // namespace phys
