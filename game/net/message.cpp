#include "game/net/message.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace game::net {

const char* messageName(MessageType t) {
    switch (t) {
    case MessageType::Offer:
        return "offer";
    case MessageType::Hello:
        return "hello";
    case MessageType::Welcome:
        return "welcome";
    case MessageType::Refuse:
        return "refuse";
    case MessageType::Command:
        return "command";
    case MessageType::Advance:
        return "advance";
    case MessageType::Handover:
        return "handover";
    case MessageType::Checkpoint:
        return "checkpoint";
    case MessageType::Bye:
        return "bye";
    case MessageType::Aiming:
        return "aiming";
    }
    return "?";
}

bool networkCommand(CommandKind k) {
    return k == CommandKind::Aim || k == CommandKind::Power || k == CommandKind::Select ||
           k == CommandKind::Fire || k == CommandKind::EndTurn;
}

namespace {

std::string checkText(const char* field, const std::string& s, std::size_t limit) {
    if (s.size() > limit)
        return std::string(field) + " is " + std::to_string(s.size()) + " bytes, at most " +
               std::to_string(limit) + " allowed";
    for (const char c : s)
        if (c < 0x20 || c > 0x7e) return std::string(field) + " has a byte outside printable ASCII";
    return "";
}

bool hexDigits(const std::string& s) {
    if (s.size() != 16) return false;
    for (const char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

/// A bare file name: letters, digits, '_', '-', '.', no leading dot (so no "..", no '/').
bool bareName(const std::string& s) {
    if (s.empty() || s[0] == '.') return false;
    for (const char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}

class Writer {
  public:
    void u8(std::uint8_t v) { out.push_back(v); }
    void u16(std::uint16_t v) {
        for (int i = 0; i < 2; ++i)
            u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i)
            u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void f64(double d) {
        std::uint64_t v;
        std::memcpy(&v, &d, sizeof v);
        u64(v);
    }
    void str(const std::string& s) {
        u8(static_cast<std::uint8_t>(s.size()));
        out.insert(out.end(), s.begin(), s.end());
    }
    std::vector<std::uint8_t> out;
};

/// Reads within [data, data + size); every read past the end sets `short_` and yields 0.
class Reader {
  public:
    Reader(const std::uint8_t* d, std::size_t n) : data_(d), size_(n) {}
    std::uint8_t u8() {
        if (pos_ >= size_) {
            short_ = true;
            return 0;
        }
        return data_[pos_++];
    }
    std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
    std::uint32_t u32() {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i)
            v |= static_cast<std::uint32_t>(u8()) << (8 * i);
        return v;
    }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i)
            v |= static_cast<std::uint64_t>(u8()) << (8 * i);
        return v;
    }
    double f64() {
        const std::uint64_t v = u64();
        double d;
        std::memcpy(&d, &v, sizeof d);
        return d;
    }
    std::string str() {
        const std::size_t n = u8();
        if (n > size_ - pos_) {
            short_ = true;
            pos_ = size_;
            return {};
        }
        std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        return s;
    }
    bool exhausted() const { return short_; }
    std::size_t left() const { return size_ - pos_; }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
    bool short_ = false;
};

void writePayload(Writer& w, const Message& m) {
    switch (m.type) {
    case MessageType::Offer:
        w.str(m.version);
        w.str(m.levelHash);
        w.str(m.levelName);
        w.str(m.name);
        w.u32(m.checkpointEvery);
        break;
    case MessageType::Hello:
        w.str(m.version);
        w.str(m.levelHash);
        w.str(m.name);
        w.u8(m.spectator ? 1 : 0);
        w.u32(m.commandIndex);
        w.u32(m.tick);
        w.str(m.token);
        break;
    case MessageType::Welcome:
        w.u8(static_cast<std::uint8_t>(m.cannon));
        w.str(m.name);
        w.u32(m.commandIndex);
        w.u32(m.tick);
        w.str(m.token);
        break;
    case MessageType::Refuse:
    case MessageType::Bye:
        w.str(m.reason);
        break;
    case MessageType::Command:
        w.u32(m.commandIndex);
        w.u32(m.tick);
        w.u8(m.player);
        w.u8(static_cast<std::uint8_t>(m.kind));
        w.f64(m.number);
        w.str(m.text);
        break;
    case MessageType::Advance:
    case MessageType::Handover:
        w.u32(m.tick);
        break;
    case MessageType::Checkpoint:
        w.u32(m.tick);
        w.u64(m.particles);
        w.u64(m.bodies);
        w.u64(m.game);
        break;
    case MessageType::Aiming:
        w.u8(m.player);
        w.f64(m.angleDeg);
        w.f64(m.speedMps);
        break;
    }
}

bool readPayload(Reader& r, Message& m, std::string& error) {
    switch (m.type) {
    case MessageType::Offer:
        m.version = r.str();
        m.levelHash = r.str();
        m.levelName = r.str();
        m.name = r.str();
        m.checkpointEvery = r.u32();
        break;
    case MessageType::Hello: {
        m.version = r.str();
        m.levelHash = r.str();
        m.name = r.str();
        const std::uint8_t s = r.u8();
        if (s > 1) {
            error = "hello: spectator flag is " + std::to_string(s) + ", expected 0 or 1";
            return false;
        }
        m.spectator = s == 1;
        m.commandIndex = r.u32();
        m.tick = r.u32();
        m.token = r.str();
        break;
    }
    case MessageType::Welcome:
        m.cannon = static_cast<std::int8_t>(r.u8());
        m.name = r.str();
        m.commandIndex = r.u32();
        m.tick = r.u32();
        m.token = r.str();
        break;
    case MessageType::Refuse:
    case MessageType::Bye:
        m.reason = r.str();
        break;
    case MessageType::Command: {
        m.commandIndex = r.u32();
        m.tick = r.u32();
        m.player = r.u8();
        const std::uint8_t k = r.u8();
        if (k > static_cast<std::uint8_t>(CommandKind::Release)) {
            error = "command: kind " + std::to_string(k) + " is unknown";
            return false;
        }
        m.kind = static_cast<CommandKind>(k);
        m.number = r.f64();
        m.text = r.str();
        break;
    }
    case MessageType::Advance:
    case MessageType::Handover:
        m.tick = r.u32();
        break;
    case MessageType::Checkpoint:
        m.tick = r.u32();
        m.particles = r.u64();
        m.bodies = r.u64();
        m.game = r.u64();
        break;
    case MessageType::Aiming:
        m.player = r.u8();
        m.angleDeg = r.f64();
        m.speedMps = r.f64();
        break;
    }
    return true;
}

} // namespace

std::string validate(const Message& m) {
    const std::string what = messageName(m.type);
    auto field = [&](const char* name, const std::string& s, std::size_t limit) {
        return checkText((what + ": " + name).c_str(), s, limit);
    };
    std::string e;
    switch (m.type) {
    case MessageType::Offer:
        if (!(e = field("version", m.version, kMaxVersionBytes)).empty()) return e;
        if (!hexDigits(m.levelHash)) return what + ": level hash must be 16 lowercase hex digits";
        if (m.levelName.size() > kMaxLevelNameBytes || !bareName(m.levelName))
            return what + ": level name must be a bare file name (letters, digits, _ - .)";
        if (!(e = field("name", m.name, kMaxNameBytes)).empty()) return e;
        if (m.checkpointEvery < 1 || m.checkpointEvery > 12000)
            return what + ": checkpoint interval " + std::to_string(m.checkpointEvery) +
                   " is outside [1, 12000] ticks";
        return "";
    case MessageType::Hello:
        if (!(e = field("version", m.version, kMaxVersionBytes)).empty()) return e;
        if (!m.levelHash.empty() && !hexDigits(m.levelHash))
            return what + ": level hash must be 16 lowercase hex digits or empty";
        if (!(e = field("name", m.name, kMaxNameBytes)).empty()) return e;
        if (m.commandIndex > kMaxCommands) return what + ": resume command count is too large";
        if (m.tick > kMaxCommandTick) return what + ": resume tick is too large";
        if (!m.token.empty() && !hexDigits(m.token))
            return what + ": seat token must be 16 lowercase hex digits or empty";
        return "";
    case MessageType::Welcome:
        if (m.cannon < -1 || m.cannon > 1) return what + ": cannon must be -1, 0 or 1";
        if (!(e = field("name", m.name, kMaxNameBytes)).empty()) return e;
        if (m.commandIndex > kMaxCommands) return what + ": command count is too large";
        if (m.tick > kMaxCommandTick) return what + ": tick is too large";
        if (!m.token.empty() && !hexDigits(m.token))
            return what + ": seat token must be 16 lowercase hex digits or empty";
        return "";
    case MessageType::Refuse:
    case MessageType::Bye:
        return field("reason", m.reason, kMaxReasonBytes);
    case MessageType::Command:
        if (m.commandIndex >= kMaxCommands) return what + ": index is too large";
        if (m.tick > kMaxCommandTick) return what + ": tick is too large";
        if (m.player > 1) return what + ": player must be 0 or 1";
        if (!networkCommand(m.kind))
            return what + ": '" + commandName(m.kind) +
                   "' is not a duel command (aim, power, select, fire, end_turn)";
        if (!std::isfinite(m.number) || std::fabs(m.number) > 1e6)
            return what + ": number must be finite and within +-1e6";
        if (m.kind == CommandKind::Select) {
            if (m.text.empty() || m.text.size() > kMaxProjectileBytes || !bareName(m.text))
                return what + ": select needs a projectile name (letters, digits, _ - .)";
        } else if (!m.text.empty()) {
            return what + ": only select carries text";
        }
        return "";
    case MessageType::Advance:
    case MessageType::Handover:
    case MessageType::Checkpoint:
        if (m.tick > kMaxCommandTick) return what + ": tick is too large";
        return "";
    case MessageType::Aiming:
        if (m.player > 1) return what + ": player must be 0 or 1";
        // The same bounds as the aim and power commands' numbers.
        if (!std::isfinite(m.angleDeg) || std::fabs(m.angleDeg) > 1e6 ||
            !std::isfinite(m.speedMps) || std::fabs(m.speedMps) > 1e6)
            return what + ": angle and power must be finite and within +-1e6";
        return "";
    }
    return "unknown message type";
}

std::vector<std::uint8_t> encode(const Message& m) {
    if (const std::string e = validate(m); !e.empty()) throw std::invalid_argument(e);
    Writer body;
    writePayload(body, m);
    Writer w;
    w.u8('A');
    w.u8('N');
    w.u8(kProtocolVersion);
    w.u8(static_cast<std::uint8_t>(m.type));
    w.u16(static_cast<std::uint16_t>(body.out.size()));
    w.out.insert(w.out.end(), body.out.begin(), body.out.end());
    return w.out;
}

Decoded decode(const std::uint8_t* data, std::size_t size) {
    Decoded d;
    if (size > kMaxMessageBytes) {
        d.error = "message of " + std::to_string(size) + " bytes is over the limit of " +
                  std::to_string(kMaxMessageBytes);
        return d;
    }
    if (size < kHeaderBytes) {
        d.error = "message of " + std::to_string(size) + " bytes is shorter than its header";
        return d;
    }
    if (data[0] != 'A' || data[1] != 'N') {
        d.error = "message does not start with the protocol's magic bytes";
        return d;
    }
    if (data[2] != kProtocolVersion) {
        d.error = "protocol version " + std::to_string(data[2]) + ", expected " +
                  std::to_string(kProtocolVersion);
        return d;
    }
    const std::uint8_t type = data[3];
    if (type < 1 || type > static_cast<std::uint8_t>(MessageType::Aiming)) {
        d.error = "message type " + std::to_string(type) + " is unknown";
        return d;
    }
    const std::size_t length = static_cast<std::size_t>(data[4] | (data[5] << 8));
    if (length != size - kHeaderBytes) {
        d.error = "payload length field says " + std::to_string(length) +
                  " bytes, the message has " + std::to_string(size - kHeaderBytes);
        return d;
    }
    Message m;
    m.type = static_cast<MessageType>(type);
    Reader r(data + kHeaderBytes, length);
    if (!readPayload(r, m, d.error)) return d;
    if (r.exhausted()) {
        d.error = std::string(messageName(m.type)) + ": payload ends early";
        return d;
    }
    if (r.left() != 0) {
        d.error = std::string(messageName(m.type)) + ": " + std::to_string(r.left()) +
                  " bytes after the last field";
        return d;
    }
    if (std::string e = validate(m); !e.empty()) {
        d.error = std::move(e);
        return d;
    }
    d.message = std::move(m);
    return d;
}

Message commandMessage(const Command& c, std::uint32_t index, int player) {
    Message m;
    m.type = MessageType::Command;
    m.commandIndex = index;
    m.tick = static_cast<std::uint32_t>(c.tick);
    m.player = static_cast<std::uint8_t>(player);
    m.kind = c.kind;
    m.number = c.number;
    m.text = c.text;
    return m;
}

Command commandOf(const Message& m) {
    Command c;
    c.tick = m.tick;
    c.kind = m.kind;
    c.number = m.number;
    c.text = m.text;
    return c;
}

} // namespace game::net
