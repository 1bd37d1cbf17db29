// SHA-256 (FIPS 180-4), for the identity of a manifest and of the results
// written so far: a resumed batch must run on the manifest it was started
// on, and must not build on bytes that did not reach the disk whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rocking::batch {

class Sha256 {
public:
    Sha256();
    void update(const void* data, std::size_t size);
    void update(const std::string& text) { update(text.data(), text.size()); }
    // The digest of everything given so far, as 64 lowercase hex digits;
    // the state is left as it was, so that more may be added after.
    std::string hex() const;
    // Whether this processor's SHA instructions compute the digests
    // (x86-64 with SHA-NI); the portable rounds otherwise.
    static bool accelerated();
    // The portable rounds even where the instructions exist: the tests
    // check the two against each other.
    void use_portable_rounds() { portable_ = true; }

private:
    void block(const unsigned char* p);
    void blocks(const unsigned char* p, std::size_t count);
    bool portable_ = false;
    std::uint32_t h_[8];
    unsigned char buffer_[64];
    std::size_t used_ = 0;
    std::uint64_t length_ = 0;  // bytes
};

std::string sha256_hex(const std::string& text);

}  // namespace rocking::batch
