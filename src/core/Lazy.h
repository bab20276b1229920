#pragma once
// A value computed when first asked for, then kept: for the parts of an item's description
// that cost milliseconds and that most uses never read (a flame's Lyapunov exponent: the
// window's spectra read it, a render does not). Copies share the one value; asking is safe
// from any thread (computed once). Qt-free.

#include <functional>
#include <memory>
#include <mutex>

namespace awb {

template <class T>
class Lazy {
public:
    Lazy() = default;  // empty: nothing to compute
    explicit Lazy(std::function<T()> make) : m_state(std::make_shared<State>(std::move(make))) {}

    explicit operator bool() const { return bool(m_state); }
    // The value (computed on the first call). Only on a Lazy that is not empty.
    const T &operator*() const
    {
        std::call_once(m_state->once, [this] { m_state->value = m_state->make(); });
        return m_state->value;
    }

private:
    struct State {
        explicit State(std::function<T()> m) : make(std::move(m)) {}
        std::function<T()> make;
        std::once_flag once;
        T value{};
    };
    std::shared_ptr<State> m_state;
};

} // namespace awb
