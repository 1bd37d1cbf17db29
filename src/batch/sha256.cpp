#include "batch/sha256.hpp"

#include <algorithm>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ROCKING_SHA_NI 1
#endif

namespace rocking::batch {

namespace {

constexpr std::uint32_t kRound[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

inline std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

#ifdef ROCKING_SHA_NI
// The processor's SHA-256 instructions (SHA-NI: Intel since Goldmont and Ice
// Lake, AMD since Zen), chosen at run time: about five times faster than
// the portable rounds, which took 44 % of a batch of 200 records' start
// (every record is hashed when the batch begins and again when a job first
// reads it) and a quarter of a batch of idle jobs (the results' digest).
// The state is FIPS 180-4's a..h, held as the instructions want it: ABEF and CDGH.
#define ROCKING_SHA_TARGET __attribute__((target("sha,sse4.1")))

ROCKING_SHA_TARGET inline void four_rounds(__m128i& abef, __m128i& cdgh, __m128i w, int group) {
    const __m128i wk = _mm_add_epi32(w, _mm_loadu_si128(reinterpret_cast<const __m128i*>(kRound + 4 * group)));
    cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);
    abef = _mm_sha256rnds2_epu32(abef, cdgh, _mm_shuffle_epi32(wk, 0x0E));
}

// w[t..t+3] of the message schedule from the four groups before it, oldest first.
ROCKING_SHA_TARGET inline __m128i next_words(__m128i w16, __m128i w12, __m128i w8, __m128i w4) {
    const __m128i partial = _mm_add_epi32(_mm_sha256msg1_epu32(w16, w12), _mm_alignr_epi8(w4, w8, 4));
    return _mm_sha256msg2_epu32(partial, w4);
}

ROCKING_SHA_TARGET void blocks_sha_ni(std::uint32_t h[8], const unsigned char* p, std::size_t blocks) {
    const __m128i big_endian = _mm_set_epi64x(0x0c0d0e0f08090a0bULL, 0x0405060700010203ULL);
    const __m128i dcba = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(h)), 0xB1);  // CDAB
    const __m128i efgh = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(h + 4)), 0x1B);
    __m128i abef = _mm_alignr_epi8(dcba, efgh, 8);
    __m128i cdgh = _mm_blend_epi16(efgh, dcba, 0xF0);
    for (; blocks > 0; --blocks, p += 64) {
        const __m128i abef_before = abef, cdgh_before = cdgh;
        __m128i w[4];
        for (int i = 0; i < 4; ++i)
            w[i] = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * i)), big_endian);
        four_rounds(abef, cdgh, w[0], 0);
        four_rounds(abef, cdgh, w[1], 1);
        four_rounds(abef, cdgh, w[2], 2);
        four_rounds(abef, cdgh, w[3], 3);
        for (int group = 4; group < 16; group += 4) {
            w[0] = next_words(w[0], w[1], w[2], w[3]);
            four_rounds(abef, cdgh, w[0], group);
            w[1] = next_words(w[1], w[2], w[3], w[0]);
            four_rounds(abef, cdgh, w[1], group + 1);
            w[2] = next_words(w[2], w[3], w[0], w[1]);
            four_rounds(abef, cdgh, w[2], group + 2);
            w[3] = next_words(w[3], w[0], w[1], w[2]);
            four_rounds(abef, cdgh, w[3], group + 3);
        }
        abef = _mm_add_epi32(abef, abef_before);
        cdgh = _mm_add_epi32(cdgh, cdgh_before);
    }
    const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);
    const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(h), _mm_blend_epi16(feba, dchg, 0xF0));      // DCBA: a..d
    _mm_storeu_si128(reinterpret_cast<__m128i*>(h + 4), _mm_alignr_epi8(dchg, feba, 8));  // HGFE: e..h
}

bool have_sha_ni() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("sha") && __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("ssse3");
}
#endif

}  // namespace

bool Sha256::accelerated() {
#ifdef ROCKING_SHA_NI
    static const bool yes = have_sha_ni();
    return yes;
#else
    return false;
#endif
}

void Sha256::blocks(const unsigned char* p, std::size_t count) {
#ifdef ROCKING_SHA_NI
    if (accelerated() && !portable_) return blocks_sha_ni(h_, p, count);
#endif
    for (; count > 0; --count, p += 64) block(p);
}

Sha256::Sha256()
    : h_{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19} {}

void Sha256::block(const unsigned char* p) {
    std::uint32_t w[64];
    for (int i = 0; i < 16; ++i)
        w[i] = (std::uint32_t(p[4 * i]) << 24) | (std::uint32_t(p[4 * i + 1]) << 16) | (std::uint32_t(p[4 * i + 2]) << 8) |
               std::uint32_t(p[4 * i + 3]);
    for (int i = 16; i < 64; ++i) {
        const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
        const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
        w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    std::uint32_t a = h_[0], b = h_[1], c = h_[2], d = h_[3], e = h_[4], f = h_[5], g = h_[6], h = h_[7];
    for (int i = 0; i < 64; ++i) {
        const std::uint32_t t1 = h + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + kRound[i] + w[i];
        const std::uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
        h = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
    }
    h_[0] += a, h_[1] += b, h_[2] += c, h_[3] += d, h_[4] += e, h_[5] += f, h_[6] += g, h_[7] += h;
}

void Sha256::update(const void* data, std::size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    length_ += size;
    if (used_ > 0) {
        const std::size_t take = std::min(size, 64 - used_);
        std::memcpy(buffer_ + used_, p, take);
        used_ += take, p += take, size -= take;
        if (used_ < 64) return;
        blocks(buffer_, 1);
        used_ = 0;
    }
    blocks(p, size / 64);
    p += size / 64 * 64;
    size %= 64;
    std::memcpy(buffer_, p, size);
    used_ = size;
}

std::string Sha256::hex() const {
    Sha256 last = *this;
    const std::uint64_t bits = length_ * 8;
    const unsigned char one = 0x80, zero = 0;
    last.update(&one, 1);
    while (last.used_ != 56) last.update(&zero, 1);
    unsigned char size[8];
    for (int i = 0; i < 8; ++i) size[i] = static_cast<unsigned char>(bits >> (56 - 8 * i));
    last.update(size, 8);
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (std::uint32_t v : last.h_)
        for (int shift = 28; shift >= 0; shift -= 4) out += digits[(v >> shift) & 0xF];
    return out;
}

std::string sha256_hex(const std::string& text) {
    Sha256 h;
    h.update(text);
    return h.hex();
}

}  // namespace rocking::batch
