
namespace game::net {
namespace {

// The fuzzer's seeds (tests/data/net_messages) are valid messages of every kind.
TEST(NetMessage, TheFuzzSeedsDecode) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(
             std::filesystem::path(ARTILLERY_SOURCE_DIR) / "tests" / "data" / "net_messages")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
        const Decoded d = decode(bytes.data(), bytes.size());
        EXPECT_EQ(d.error, "") << entry.path();
        if (d.message) EXPECT_EQ(encode(*d.message), bytes) << entry.path();
        ++files;
    }
    EXPECT_EQ(files, 8);
}

} // namespace
} // namespace game::net
