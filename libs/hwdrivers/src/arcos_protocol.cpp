/* hslam: ARCOS packet codec (see arcos_protocol.h). */
#include <hslam/hwdrivers/arcos_protocol.h>

#include <stdexcept>

namespace hslam::hwdrivers::arcos
{
uint16_t checksum(const uint8_t* payload, size_t n)
{
	uint32_t sum = 0;
	size_t i = 0;
	for (; i + 1 < n; i += 2)
	{
		sum += (static_cast<uint32_t>(payload[i]) << 8) | payload[i + 1];
		sum &= 0xFFFF;
	}
	if (i < n) sum ^= payload[i];
	return static_cast<uint16_t>(sum);
}

std::vector<uint8_t> framePacket(const std::vector<uint8_t>& payload)
{
	if (payload.empty() || payload.size() > MAX_PAYLOAD_BYTES)
		throw std::invalid_argument("ARCOS payload must have 1.." + std::to_string(MAX_PAYLOAD_BYTES) + " bytes, got " +
									std::to_string(payload.size()));
	std::vector<uint8_t> out;
	out.reserve(payload.size() + 5);
	out.push_back(HEADER0);
	out.push_back(HEADER1);
	out.push_back(static_cast<uint8_t>(payload.size() + 2));
	out.insert(out.end(), payload.begin(), payload.end());
	const uint16_t ck = checksum(payload);
	out.push_back(static_cast<uint8_t>(ck >> 8));
	out.push_back(static_cast<uint8_t>(ck & 0xFF));
	return out;
}

std::vector<uint8_t> encodeCommand(uint8_t command) { return framePacket({command}); }

std::vector<uint8_t> encodeCommandInt(uint8_t command, int value)
{
	if (value > 65535 || value < -65535)
		throw std::out_of_range("ARCOS integer argument out of range: " + std::to_string(value));
	const unsigned magnitude = static_cast<unsigned>(value < 0 ? -value : value);
	return framePacket({command, value < 0 ? ARG_INT_NEG : ARG_INT_POS, static_cast<uint8_t>(magnitude & 0xFF),
						static_cast<uint8_t>(magnitude >> 8)});
}

std::vector<uint8_t> encodeCommandString(uint8_t command, const std::string& value)
{
	if (value.size() > MAX_PAYLOAD_BYTES - 3) throw std::out_of_range("ARCOS string argument too long");
	std::vector<uint8_t> payload{command, ARG_STRING, static_cast<uint8_t>(value.size())};
	for (char ch : value) payload.push_back(static_cast<uint8_t>(ch));
	return framePacket(payload);
}

std::optional<TCommand> decodeCommand(const std::vector<uint8_t>& payload)
{
	if (payload.empty()) return std::nullopt;
	TCommand c;
	c.command = payload[0];
	if (payload.size() == 1) return c;
	const uint8_t type = payload[1];
	if (type == ARG_INT_POS || type == ARG_INT_NEG)
	{
		if (payload.size() < 4) return std::nullopt;
		const int magnitude = payload[2] | (payload[3] << 8);
		c.arg = TCommand::INT;
		c.intValue = type == ARG_INT_NEG ? -magnitude : magnitude;
		return c;
	}
	if (type == ARG_STRING)
	{
		if (payload.size() < 3 || payload.size() < 3u + payload[2]) return std::nullopt;
		c.arg = TCommand::STRING;
		c.stringValue.assign(payload.begin() + 3, payload.begin() + 3 + payload[2]);
		return c;
	}
	// SYNC echoes and some firmware replies carry extra bytes without a type.
	return c;
}

void CArcosPacketParser::feed(const uint8_t* data, size_t n)
{
	compact();
	m_buf.insert(m_buf.end(), data, data + n);
}

void CArcosPacketParser::clear()
{
	m_buf.clear();
	m_pos = 0;
}

void CArcosPacketParser::compact()
{
	if (m_pos == 0) return;
	m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<std::ptrdiff_t>(m_pos));
	m_pos = 0;
}

bool CArcosPacketParser::validPacketAfter(size_t from) const
{
	for (size_t q = from; q + 2 < m_buf.size(); ++q)
	{
		if (m_buf[q] != HEADER0 || m_buf[q + 1] != HEADER1) continue;
		const size_t n = m_buf[q + 2];
		if (n < 3 || n + 3 > MAX_PACKET_BYTES || m_buf.size() - q < n + 3) continue;
		const uint16_t received = static_cast<uint16_t>((m_buf[q + 1 + n] << 8) | m_buf[q + 2 + n]);
		if (checksum(&m_buf[q + 3], n - 2) == received) return true;
	}
	return false;
}

bool CArcosPacketParser::next(std::vector<uint8_t>& payload)
{
	for (;;)
	{
		// Find the header.
		size_t p = m_pos;
		while (p + 1 < m_buf.size() && !(m_buf[p] == HEADER0 && m_buf[p + 1] == HEADER1)) ++p;
		if (p + 1 >= m_buf.size())
		{
			// Keep a trailing FA: it may be the start of the next header.
			const size_t keep = (!m_buf.empty() && p < m_buf.size() && m_buf[p] == HEADER0) ? 1 : 0;
			const size_t newPos = m_buf.size() - keep;
			if (newPos > m_pos) m_stats.garbageBytes += newPos - m_pos;
			m_pos = std::max(m_pos, newPos);
			return false;
		}
		m_stats.garbageBytes += p - m_pos;
		m_pos = p;
		if (m_buf.size() - p < 3) return false;
		const size_t n = m_buf[p + 2];
		if (n < 3 || n + 3 > MAX_PACKET_BYTES)
		{
			++m_stats.badLengths;
			m_stats.garbageBytes += 1;
			m_pos = p + 1;
			continue;
		}
		if (m_buf.size() - p < n + 3)
		{
			// Incomplete. If a complete valid packet starts at a later header,
			// this one was truncated (device reset, lost bytes): drop it now
			// instead of waiting for bytes that belong to the next packets.
			if (!validPacketAfter(p + 1)) return false;
			++m_stats.badChecksums;
			m_stats.garbageBytes += 1;
			m_pos = p + 1;
			continue;
		}
		const uint8_t* body = &m_buf[p + 3];
		const size_t bodyLen = n - 2;
		const uint16_t received = static_cast<uint16_t>((m_buf[p + 1 + n] << 8) | m_buf[p + 2 + n]);
		if (checksum(body, bodyLen) != received)
		{
			// Resync from the byte after this header: a valid packet may start
			// inside a corrupted or truncated one.
			++m_stats.badChecksums;
			m_stats.garbageBytes += 1;
			m_pos = p + 1;
			continue;
		}
		payload.assign(body, body + bodyLen);
		m_pos = p + 3 + n;
		++m_stats.packets;
		return true;
	}
}

}  // namespace hslam::hwdrivers::arcos
