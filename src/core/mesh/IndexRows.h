#pragma once
// Rows of indices of different lengths in two flat arrays (compressed rows, as OpenSubdiv's Vtr
// keeps its relations): a face's vertex loop, a vertex's ring of edges. A mesh of a million faces
// is two allocations, not a million. Internal to the mesh room. Qt-free.

#include "core/BigAllocator.h"

#include <cstddef>
#include <initializer_list>
#include <span>
#include <vector>

namespace awb {

class IndexRows {
public:
    IndexRows() = default;
    explicit IndexRows(const std::vector<std::vector<int>> &rows)
    {
        std::size_t count = 0;
        for (const auto &row : rows)
            count += row.size();
        reserve(rows.size(), count);
        for (const auto &row : rows)
            push_back(row);
    }

    std::size_t size() const { return m_start.size() - 1; }
    bool empty() const { return size() == 0; }
    std::span<const int> operator[](std::size_t i) const
    {
        return {m_values.data() + m_start[i], std::size_t(m_start[i + 1] - m_start[i])};
    }
    std::span<int> row(std::size_t i)
    {
        return {m_values.data() + m_start[i], std::size_t(m_start[i + 1] - m_start[i])};
    }
    // Where row i begins in values() (start(size()) is the count of values).
    int start(std::size_t i) const { return m_start[i]; }
    const BigVector<int> &starts() const { return m_start; }
    const BigVector<int> &values() const { return m_values; }

    void reserve(std::size_t rows, std::size_t values)
    {
        m_start.reserve(rows + 1);
        m_values.reserve(values);
    }
    void push_back(std::span<const int> row)
    {
        m_values.insert(m_values.end(), row.begin(), row.end());
        m_start.push_back(int(m_values.size()));
    }
    void push_back(std::initializer_list<int> row)
    {
        push_back(std::span<const int>(row.begin(), row.size()));
    }
    // Rows of the lengths of `model`'s, every value `fill`.
    static IndexRows shapedLike(const IndexRows &model, int fill)
    {
        IndexRows out;
        out.m_start = model.m_start;
        out.m_values.assign(model.m_values.size(), fill);
        return out;
    }

    std::vector<std::vector<int>> toVectors() const
    {
        std::vector<std::vector<int>> out(size());
        for (std::size_t i = 0; i < size(); ++i)
            out[i].assign((*this)[i].begin(), (*this)[i].end());
        return out;
    }

    class const_iterator {
    public:
        const_iterator(const IndexRows *rows, std::size_t i) : m_rows(rows), m_i(i) {}
        std::span<const int> operator*() const { return (*m_rows)[m_i]; }
        const_iterator &operator++()
        {
            ++m_i;
            return *this;
        }
        bool operator==(const const_iterator &o) const { return m_i == o.m_i; }

    private:
        const IndexRows *m_rows;
        std::size_t m_i;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

private:
    BigVector<int> m_start{0};
    BigVector<int> m_values;
};

} // namespace awb
