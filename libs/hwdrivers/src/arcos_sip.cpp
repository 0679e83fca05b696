/* hslam: ARCOS SIP decoding/encoding (see arcos_sip.h). */
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/arcos_sip.h>

namespace hslam::hwdrivers::arcos
{
namespace
{
/** Bounds-checked little-endian reader. */
class CReader
{
   public:
	CReader(const uint8_t* d, size_t n) : m_d(d), m_n(n) {}
	bool u8(uint8_t& v)
	{
		if (m_i + 1 > m_n) return false;
		v = m_d[m_i++];
		return true;
	}
	bool u16(uint16_t& v)
	{
		if (m_i + 2 > m_n) return false;
		v = static_cast<uint16_t>(m_d[m_i] | (m_d[m_i + 1] << 8));
		m_i += 2;
		return true;
	}
	bool i16(int16_t& v)
	{
		uint16_t u;
		if (!u16(u)) return false;
		v = static_cast<int16_t>(u);
		return true;
	}

   private:
	const uint8_t* m_d;
	size_t m_n, m_i = 0;
};

void put16(std::vector<uint8_t>& out, uint16_t v)
{
	out.push_back(static_cast<uint8_t>(v & 0xFF));
	out.push_back(static_cast<uint8_t>(v >> 8));
}
}  // namespace

std::optional<TSip> decodeSip(const uint8_t* payload, size_t n)
{
	TSip s;
	CReader r(payload, n);
	uint8_t count = 0;
	if (!r.u8(s.type) || !isStandardSip(s.type)) return std::nullopt;
	if (!(r.u16(s.xpos_raw) && r.u16(s.ypos_raw) && r.i16(s.thpos_raw) && r.i16(s.vel_left_raw) &&
		  r.i16(s.vel_right_raw) && r.u8(s.battery_dV) && r.u16(s.stall_bump) && r.i16(s.control) && r.u16(s.flags) &&
		  r.u8(s.compass) && r.u8(count)))
		return std::nullopt;
	s.xpos_raw &= 0x7FFF;  // only 15 bits are used (Aria masks the same way)
	s.ypos_raw &= 0x7FFF;
	s.sonars.resize(count);
	for (auto& so : s.sonars)
		if (!(r.u8(so.index) && r.u16(so.range_raw))) return std::nullopt;
	s.has_tail = r.u8(s.grip) && r.u8(s.anport) && r.u8(s.analog) && r.u8(s.digin) && r.u8(s.digout) &&
				 r.u16(s.battery_x10) && r.u8(s.charge_state) && r.i16(s.rotvel_x10) && r.u16(s.fault_flags);
	return s;
}

std::vector<uint8_t> encodeSip(const TSip& s)
{
	std::vector<uint8_t> out;
	out.reserve(40 + 3 * s.sonars.size());
	out.push_back(s.type);
	put16(out, s.xpos_raw & 0x7FFF);
	put16(out, s.ypos_raw & 0x7FFF);
	put16(out, static_cast<uint16_t>(s.thpos_raw));
	put16(out, static_cast<uint16_t>(s.vel_left_raw));
	put16(out, static_cast<uint16_t>(s.vel_right_raw));
	out.push_back(s.battery_dV);
	put16(out, s.stall_bump);
	put16(out, static_cast<uint16_t>(s.control));
	put16(out, s.flags);
	out.push_back(s.compass);
	out.push_back(static_cast<uint8_t>(s.sonars.size()));
	for (const auto& so : s.sonars)
	{
		out.push_back(so.index);
		put16(out, so.range_raw);
	}
	if (s.has_tail)
	{
		for (uint8_t b : {s.grip, s.anport, s.analog, s.digin, s.digout}) out.push_back(b);
		put16(out, s.battery_x10);
		out.push_back(s.charge_state);
		put16(out, static_cast<uint16_t>(s.rotvel_x10));
		put16(out, s.fault_flags);
	}
	return out;
}

}  // namespace hslam::hwdrivers::arcos
