#include "batch/row_digest.hpp"

#include <xxhash.h>

#include <cstdio>

namespace rocking::batch {

std::uint64_t row_digest(std::string_view row, std::size_t job) {
    return XXH3_64bits_withSeed(row.data(), row.size(), static_cast<XXH64_hash_t>(job) + 1);
}

std::uint64_t header_digest(std::string_view header) { return XXH3_64bits_withSeed(header.data(), header.size(), 0); }

std::string digest_hex(std::uint64_t digest) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(digest));
    return text;
}

void RowsDigest::feed(const char* data, std::size_t size) {
    std::size_t start = 0;
    for (std::size_t k = 0; k < size; ++k) {
        // A doubled quote inside a quoted cell flips twice: no need to tell it apart.
        if (data[k] == '"') quoted_ = !quoted_;
        if (data[k] != '\n' || quoted_) continue;
        const std::string_view piece(data + start, k + 1 - start);
        if (carry_.empty()) sum_ += row_digest(piece, next_);
        else {
            carry_.append(piece);
            sum_ += row_digest(carry_, next_);
            carry_.clear();
        }
        ++next_, ++rows_;
        start = k + 1;
    }
    carry_.append(data + start, size - start);
}

}  // namespace rocking::batch
