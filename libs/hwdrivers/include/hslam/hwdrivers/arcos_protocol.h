/* hslam: ARCOS / P2OS client-server packet codec (Pioneer P3-DX), pure functions.
 *
 * Packet (both directions): FA FB N <payload> CKhi CKlo, N = payload bytes + 2
 * (the checksum), total <= 200 bytes. The first payload byte is the command
 * number (client -> robot) or the packet type (robot -> client).
 * Checksum: sum of big-endian 16-bit words of the payload mod 2^16, an odd last
 * byte XORed in, transmitted high byte first (all data fields are little-endian).
 * Integer arguments: 0x3B + uint16 LE for >= 0, 0x1B + |value| as uint16 LE for < 0
 * (magnitude, not two's complement); strings: 0x2B + length byte + chars.
 * Sources: ../shared/notes/mrpt-plugins-and-protocols.md section 3 (AriaCoda
 * ArRobotPacket, ROS p2os). The thesis robot is a Pioneer P3-DX (thesis section 4.1).
 *
 * CArcosPacketParser turns an arbitrary byte stream (garbage, truncated or
 * corrupted packets included) into the payloads of valid packets, resyncing on
 * the next FA FB header, and counts what it had to drop. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hslam::hwdrivers::arcos
{
constexpr uint8_t HEADER0 = 0xFA;
constexpr uint8_t HEADER1 = 0xFB;
constexpr size_t MAX_PACKET_BYTES = 200;  //!< header + N byte + N
constexpr size_t MAX_PAYLOAD_BYTES = MAX_PACKET_BYTES - 5;

/** Client command numbers (AriaCoda ArCommands.h). */
enum ECommand : uint8_t
{
	CMD_PULSE = 0,
	CMD_SYNC0 = 0,
	CMD_SYNC1 = 1,
	CMD_SYNC2 = 2,
	CMD_OPEN = 1,
	CMD_CLOSE = 2,
	CMD_ENABLE = 4,
	CMD_SETA = 5,
	CMD_SETV = 6,
	CMD_SETO = 7,
	CMD_VEL = 11,
	CMD_CONFIG = 18,
	CMD_RVEL = 21,
	CMD_SONAR = 28,
	CMD_STOP = 29,
	CMD_ESTOP = 55
};

/** Argument type bytes. */
constexpr uint8_t ARG_INT_POS = 0x3B;
constexpr uint8_t ARG_INT_NEG = 0x1B;
constexpr uint8_t ARG_STRING = 0x2B;

/** Server packet types. */
constexpr uint8_t SIP_STOPPED = 0x32;
constexpr uint8_t SIP_MOVING = 0x33;
inline bool isStandardSip(uint8_t type) { return type == SIP_STOPPED || type == SIP_MOVING; }

/** ARCOS checksum of a payload. */
uint16_t checksum(const uint8_t* payload, size_t n);
inline uint16_t checksum(const std::vector<uint8_t>& payload) { return checksum(payload.data(), payload.size()); }

/** Complete packet (header, N, payload, checksum). Throws std::invalid_argument
 * if the payload is empty or longer than MAX_PAYLOAD_BYTES. */
std::vector<uint8_t> framePacket(const std::vector<uint8_t>& payload);

/** Client commands: without argument, with a signed integer (|value| <= 65535,
 * else std::out_of_range), with a string (<= 190 chars). */
std::vector<uint8_t> encodeCommand(uint8_t command);
std::vector<uint8_t> encodeCommandInt(uint8_t command, int value);
std::vector<uint8_t> encodeCommandString(uint8_t command, const std::string& value);

/** A decoded client command (server/emulator side). */
struct TCommand
{
	enum EArg
	{
		NONE,
		INT,
		STRING
	};
	uint8_t command = 0;
	EArg arg = NONE;
	int intValue = 0;
	std::string stringValue;
};

/** Decodes a command payload; nullopt if the argument is malformed. */
std::optional<TCommand> decodeCommand(const std::vector<uint8_t>& payload);

/** Incremental stream parser with resynchronisation. */
class CArcosPacketParser
{
   public:
	struct TStats
	{
		uint64_t packets = 0;  //!< valid packets returned
		uint64_t badChecksums = 0;  //!< complete frames whose checksum failed
		uint64_t badLengths = 0;  //!< headers with an impossible N byte
		uint64_t garbageBytes = 0;  //!< bytes skipped while looking for a header
	};

	/** Appends received bytes. */
	void feed(const uint8_t* data, size_t n);
	void feed(const std::vector<uint8_t>& data) { feed(data.data(), data.size()); }

	/** Extracts the next valid payload; false if none is complete yet. */
	bool next(std::vector<uint8_t>& payload);

	/** Drops buffered bytes (after a reconnection); keeps the statistics. */
	void clear();

	/** Bytes buffered but not yet consumed (a partial packet). */
	size_t pending() const { return m_buf.size() - m_pos; }

	const TStats& stats() const { return m_stats; }

   private:
	void compact();
	/** True if a complete packet with a valid checksum starts at or after `from`. */
	bool validPacketAfter(size_t from) const;

	std::vector<uint8_t> m_buf;
	size_t m_pos = 0;  //!< first unconsumed byte
	TStats m_stats;
};

}  // namespace hslam::hwdrivers::arcos
