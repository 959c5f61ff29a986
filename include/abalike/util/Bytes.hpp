#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace abalike
{

/// Plain values packed into bytes and read back in the same order, within one program (no portable format: the
/// bytes travel from a copy of the process to the process itself, runInProcessCopy).
class BytesOut
{
public:
    template <typename T>
    BytesOut& put(const T& value)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        m_bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
        return *this;
    }

    template <typename T>
    BytesOut& putVector(const std::vector<T>& values)
    {
        put(values.size());
        for (const T& value : values)
            put(value);
        return *this;
    }

    std::string take() { return std::move(m_bytes); }

private:
    std::string m_bytes;
};

/// Reads what BytesOut packed; throws std::runtime_error when the bytes run out.
class BytesIn
{
public:
    explicit BytesIn(std::string_view bytes) : m_bytes(bytes) {}

    template <typename T>
    T get()
    {
        static_assert(std::is_trivially_copyable_v<T> && std::is_default_constructible_v<T>);
        if (m_bytes.size() < sizeof(T))
            throw std::runtime_error("BytesIn: the bytes ended early");
        T value;
        std::memcpy(&value, m_bytes.data(), sizeof value);
        m_bytes.remove_prefix(sizeof value);
        return value;
    }

    template <typename T>
    std::vector<T> getVector()
    {
        const auto count = get<std::size_t>();
        if (count > m_bytes.size() / sizeof(T))
            throw std::runtime_error("BytesIn: the bytes ended early");
        std::vector<T> values;
        values.reserve(count);
        for (std::size_t i = 0; i < count; ++i)
            values.push_back(get<T>());
        return values;
    }

private:
    std::string_view m_bytes;
};

} // namespace abalike
