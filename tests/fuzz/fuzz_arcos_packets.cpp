/* Fuzz target: a byte stream from the robot through the ARCOS packet parser
 * and the SIP decoder (libs/hwdrivers), fed in pieces as a link delivers it. */
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/arcos_sip.h>

#include <algorithm>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_arcos_packets(const uint8_t* data, size_t size)
{
	hwdrivers::arcos::CArcosPacketParser parser;
	std::vector<uint8_t> payload;
	// Piece sizes from the first byte, so both whole and split packets occur.
	const size_t piece = size > 0 ? 1 + data[0] % 64 : 1;
	for (size_t at = 0; at < size; at += piece)
	{
		parser.feed(data + at, std::min(piece, size - at));
		while (parser.next(payload)) hwdrivers::arcos::decodeSip(payload);
	}
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_arcos_packets)
