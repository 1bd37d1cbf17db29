// SHA-256 (FIPS 180-4), for the identity of a manifest, of a record and of
// the results written so far: a resumed batch must run on the manifest it was
// started on, and must not build on bytes that did not reach the disk whole.
// The rounds are OpenSSL's libcrypto (EVP), which picks the processor's SHA
// instructions where it has them; this class keeps the incremental use the
// batch needs: a digest read in the middle, with more bytes added after.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

struct evp_md_ctx_st;

namespace rocking::batch {

class Sha256 {
public:
    Sha256();
    Sha256(const Sha256& other);
    Sha256& operator=(const Sha256& other);
    Sha256(Sha256&&) noexcept = default;
    Sha256& operator=(Sha256&&) noexcept = default;
    ~Sha256();
    void update(const void* data, std::size_t size);
    void update(const std::string& text) { update(text.data(), text.size()); }
    // The digest of everything given so far, as 64 lowercase hex digits;
    // the state is left as it was, so that more may be added after.
    std::string hex() const;

private:
    struct Free {
        void operator()(evp_md_ctx_st* ctx) const;
    };
    std::unique_ptr<evp_md_ctx_st, Free> ctx_;
};

std::string sha256_hex(const std::string& text);

}  // namespace rocking::batch
