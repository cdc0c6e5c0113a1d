// A symmetric sparse matrix's upper triangle assembled from its terms
// straight into compressed columns (rig/BoneHeatSolver's L + A H and its
// mirror-reduced R^T (L + A H) R).
#pragma once

#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

namespace rigmesh {

// The upper triangle of an n x n matrix from terms (row, column, value),
// row <= column, that terms(add) passes to add in the same order on every
// call. Each entry is the sum of its terms in that order, the first taken as
// it is: Eigen's setFromTriplets on the same terms sums a row's duplicates in
// insertion order, so the matrix is the same bit for bit, written straight
// into compressed columns (rows sorted) without the triplets (16 bytes
// each, about 6 per face) and setFromTriplets' transposed copy, which were
// most of the assembly's time and its page faults in perf.
template <typename Terms>
void upperFromTerms(int n, const Terms& terms, Eigen::SparseMatrix<double>& matrix) {
    std::vector<int> columnStart(static_cast<std::size_t>(n) + 1, 0);
    terms([&](int, int column, double) { ++columnStart[column + 1]; });
    for (int v = 0; v < n; ++v) {
        columnStart[v + 1] += columnStart[v];
    }
    std::vector<int> rows(columnStart[n]);
    {
        std::vector<int> next(columnStart.begin(), columnStart.end() - 1);
        terms([&](int row, int column, double) { rows[next[column]++] = row; });
    }
    matrix.resize(n, n);
    int* const start = matrix.outerIndexPtr();
    int entries = 0;
    for (int v = 0; v < n; ++v) {
        const auto first = rows.begin() + columnStart[v];
        const auto last = rows.begin() + columnStart[v + 1];
        std::sort(first, last);
        start[v] = entries;
        entries += static_cast<int>(std::unique(first, last) - first);
    }
    start[n] = entries;
    matrix.resizeNonZeros(entries);
    int* const inner = matrix.innerIndexPtr();
    for (int v = 0; v < n; ++v) {
        std::copy(rows.begin() + columnStart[v],
                  rows.begin() + columnStart[v] + (start[v + 1] - start[v]), inner + start[v]);
    }
    double* const value = matrix.valuePtr();
    std::vector<char> written(entries, 0);
    terms([&](int row, int column, double term) {
        int slot = start[column];
        while (inner[slot] != row) {
            ++slot;
        }
        value[slot] = written[slot] ? value[slot] + term : term;
        written[slot] = 1;
    });
}

}  // namespace rigmesh
