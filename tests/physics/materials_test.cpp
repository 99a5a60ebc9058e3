// The material table: the measured presets, the combine rule, pair overrides,
// and the projectile presets built on them.
#include "physics/materials.h"
#include "physics/projectiles.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

// Claypool, Game Physics (ch. 10): restitution of balls dropped from 92 cm onto a floor.
TEST(Materials, MeasuredPresetsAgainstTheFloor) {
    const MaterialTable t;
    const struct {
        const char* name;
        double e;
    } measured[] = {{"golf", 0.858},
                 {"tennis", 0.712},
                 {"billiard", 0.804},
                 {"hand-ball", 0.752},
                 {"wooden", 0.603},
                 {"steel-bearing", 0.597},
                 {"glass-marble", 0.658},
                 {"rubber-band-ball", 0.828},
                 {"hollow-hard-plastic", 0.688},
                 {"perfectly-elastic", 1.0},
                 {"perfectly-plastic", 0.0}};
    ASSERT_EQ(std::size(kRestitutionPresets), std::size(measured));
    for (std::size_t i = 0; i < std::size(measured); ++i) {
        const auto id = t.find(measured[i].name);
        ASSERT_TRUE(id) << measured[i].name;
        EXPECT_EQ(*id, kRestitutionPresets[i].id);
        EXPECT_DOUBLE_EQ(t[*id].restitution, measured[i].e);
        // Against the rigid reference floor a ball bounces with its own measured e.
        EXPECT_DOUBLE_EQ(t.pair(*id, material::kFloor).restitution, measured[i].e);
        EXPECT_DOUBLE_EQ(t.pair(material::kFloor, *id).restitution, measured[i].e);
        EXPECT_EQ(validate(t[*id]), "");
    }
}

// The combine rule: e = e_a e_b, mu = sqrt(mu_a mu_b), symmetric.
TEST(Materials, CombineRuleForPairsWithoutAnEntry) {
    const MaterialTable t;
    const auto golf = material::kGolf, steel = material::kSteelBearing;
    EXPECT_DOUBLE_EQ(t.pair(golf, steel).restitution, 0.858 * 0.597);
    EXPECT_DOUBLE_EQ(t.pair(steel, golf).restitution, 0.858 * 0.597);
    EXPECT_DOUBLE_EQ(t.pair(golf, golf).restitution, 0.858 * 0.858);
    EXPECT_DOUBLE_EQ(t.pair(golf, steel).staticFriction,
                     std::sqrt(t[golf].staticFriction * t[steel].staticFriction));
    EXPECT_DOUBLE_EQ(t.pair(golf, steel).dynamicFriction,
                     std::sqrt(t[golf].dynamicFriction * t[steel].dynamicFriction));
    // Perfectly plastic wins against anything; perfectly elastic is neutral.
    EXPECT_EQ(t.pair(material::kPerfectlyPlastic, material::kRubberBandBall).restitution, 0.0);
    EXPECT_DOUBLE_EQ(t.pair(material::kPerfectlyElastic, material::kTennis).restitution, 0.712);
}

// A pair entry overrides the rule in both orders and leaves every other pair alone.
TEST(Materials, PairEntryOverridesTheRule) {
    MaterialTable t;
    t.setPair(material::kGolf, material::kWooden, {0.9, 0.1, 0.05});
    EXPECT_DOUBLE_EQ(t.pair(material::kWooden, material::kGolf).restitution, 0.9);
    EXPECT_DOUBLE_EQ(t.pair(material::kGolf, material::kWooden).staticFriction, 0.1);
    EXPECT_DOUBLE_EQ(t.pair(material::kGolf, material::kTennis).restitution, 0.858 * 0.712);
    // Added materials keep the override and combine with everything.
    const auto clay = t.add({"clay", 0.1, 0.9, 0.8});
    ASSERT_TRUE(clay);
    EXPECT_DOUBLE_EQ(t.pair(material::kWooden, material::kGolf).restitution, 0.9);
    EXPECT_DOUBLE_EQ(t.pair(*clay, material::kFloor).restitution, 0.1);
    // Bad materials are refused, with a reason.
    EXPECT_FALSE(t.add({"clay", 0.2, 0.5, 0.4}));   // name taken
    EXPECT_FALSE(t.add({"rubber", 1.2, 0.5, 0.4})); // e > 1
    EXPECT_EQ(validate(Material{"ice", 0.5, 0.1, 0.2}),
              "material 'ice': dynamic friction must be in [0, static friction]");
}

// Projectile presets: published sizes and masses (sources in projectiles.cpp), their
// materials, and the particle they make.
TEST(Projectiles, PresetsPairMaterialWithMassSizeAndDrag) {
    const auto golf = projectileFromName("golf-ball");
    ASSERT_TRUE(golf);
    EXPECT_DOUBLE_EQ(golf->mass, 0.04593);     // Rules of Golf: at most 45.93 g
    EXPECT_DOUBLE_EQ(golf->diameter, 0.04267); // at least 42.67 mm
    EXPECT_EQ(golf->material, material::kGolf);
    const ParticleDef pd = particleDef(*golf, {1.0, 2.0}, {3.0, 4.0});
    EXPECT_DOUBLE_EQ(pd.radius, 0.021335);
    EXPECT_DOUBLE_EQ(pd.mass, 0.04593);
    EXPECT_DOUBLE_EQ(pd.dragCoefficient, 0.25);
    EXPECT_EQ(pd.position, (Vec2{1.0, 2.0}));
    for (const char* name : {"cannonball", "golf-ball", "tennis-ball", "baseball", "billiard-ball",
                             "steel-ball", "glass-marble", "hand-ball"})
        EXPECT_TRUE(projectileFromName(name)) << name;
    EXPECT_FALSE(projectileFromName("bowling-ball"));
    // The cannonball: 12 lb of cast iron (7200 kg/m^3) is a 113 mm sphere.
    const auto c = *projectileFromName("cannonball");
    const double density = c.mass / (std::acos(-1.0) / 6.0 * c.diameter * c.diameter * c.diameter);
    EXPECT_NEAR(density, 7200.0, 150.0);
    EXPECT_NEAR(c.mass, 12.0 * 0.45359237, 1e-3);
    // Every preset's material is a real entry of the table.
    const MaterialTable t;
    for (const auto& p : projectilePresets())
        EXPECT_LT(p.material, t.size()) << p.name;
}
