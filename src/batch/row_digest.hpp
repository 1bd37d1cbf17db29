// The checksum a results file's state keeps of the bytes it counts, built so
// that no one process need see every byte: the ranks of an MPI run write
// their own rows (cluster_mpi.cpp), and rank 0 learns of each chunk only its
// length and this sum.  A sum of one hash a row, each seeded by the row's
// job, combines in any order and any cut into chunks:
//
//   D = XXH3_64(header, seed 0) + sum over jobs i of XXH3_64(row_i, seed i + 1)   (mod 2^64)
//
// where row_i is job i's row with its newline.  The seed puts each row at its
// place: two rows swapped, or a row written at another's offset, change D.
// It guards against damage (a torn write, a file edited or cut), not against
// an adversary; the inputs' identities stay SHA-256 (sha256.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rocking::batch {

// XXH3_64(row, seed job + 1): one term of D.  `row` with its newline.
std::uint64_t row_digest(std::string_view row, std::size_t job);
// XXH3_64(header, seed 0): D's first term.
std::uint64_t header_digest(std::string_view header);
// D as the state file writes it: 16 lowercase hex digits.
std::string digest_hex(std::uint64_t digest);

// D's row terms of a stream of rows read back, fed in pieces of any size:
// a row ends at a line feed outside a quoted cell (RFC 4180: a quoted cell
// may hold line breaks, as the writer quotes them), and the first row fed is
// job `first`'s.  Not libcsv: these are rows this program wrote (csv_cell),
// where a quote's parity is all there is to know, and a resume reads every
// byte written (200 GB for 10^9 rows), which libcsv's 45 instructions a byte
// would take longer to read than the disk; a row it splits wrongly (a file
// damaged) only makes D differ.
class RowsDigest {
public:
    explicit RowsDigest(std::size_t first = 0) : next_(first) {}
    void feed(const char* data, std::size_t size);
    std::uint64_t sum() const { return sum_; }
    // The rows ended so far, and whether bytes are left after the last one.
    std::size_t rows() const { return rows_; }
    bool row_open() const { return !carry_.empty(); }

private:
    std::size_t next_, rows_ = 0;
    std::uint64_t sum_ = 0;
    bool quoted_ = false;
    std::string carry_;  // the row begun in an earlier piece
};

}  // namespace rocking::batch
