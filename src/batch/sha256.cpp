#include "batch/sha256.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace rocking::batch {

namespace {

// Fetched once: OpenSSL 3 looks the algorithm up in its provider on every
// EVP_sha256() initialisation otherwise, which costs more than hashing a row.
const EVP_MD* sha256_md() {
    static EVP_MD* md = EVP_MD_fetch(nullptr, "SHA256", nullptr);
    if (md == nullptr) throw std::runtime_error("libcrypto: no SHA-256 (EVP_MD_fetch failed)");
    return md;
}

// libcrypto reports failure by return value; none is expected on memory
// that exists, so one is an error of the library or the machine.
void checked(int ok, const char* what) {
    if (ok != 1) throw std::runtime_error(std::string("libcrypto: ") + what + " failed");
}

}  // namespace

void Sha256::Free::operator()(evp_md_ctx_st* ctx) const { EVP_MD_CTX_free(ctx); }

Sha256::Sha256() : ctx_(EVP_MD_CTX_new()) {
    if (!ctx_) throw std::bad_alloc();
    checked(EVP_DigestInit_ex(ctx_.get(), sha256_md(), nullptr), "EVP_DigestInit_ex");
}

Sha256::Sha256(const Sha256& other) : ctx_(EVP_MD_CTX_new()) {
    if (!ctx_) throw std::bad_alloc();
    checked(EVP_MD_CTX_copy_ex(ctx_.get(), other.ctx_.get()), "EVP_MD_CTX_copy_ex");
}

Sha256& Sha256::operator=(const Sha256& other) {
    if (this != &other) *this = Sha256(other);
    return *this;
}

Sha256::~Sha256() = default;

void Sha256::update(const void* data, std::size_t size) {
    if (size > 0) checked(EVP_DigestUpdate(ctx_.get(), data, size), "EVP_DigestUpdate");
}

std::string Sha256::hex() const {
    Sha256 last(*this);
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    checked(EVP_DigestFinal_ex(last.ctx_.get(), digest, &size), "EVP_DigestFinal_ex");
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (unsigned int i = 0; i < size; ++i) out += {digits[digest[i] >> 4], digits[digest[i] & 0xF]};
    return out;
}

std::string sha256_hex(const std::string& text) {
    Sha256 h;
    h.update(text);
    return h.hex();
}

}  // namespace rocking::batch
