#include "common/gl_call_log.h"

namespace wb::ex {
namespace {
struct State {
    bool available = false, open = false;
    int depth = 0; // > 0 inside a noted call (GLU's own GL calls are not the student's)
    std::vector<int> calls;
};
State& state() {
    static State s;
    return s;
}
} // namespace

bool glCallLogAvailable() {
    return state().available;
}
void glCallLogSetAvailable() {
    state().available = true;
}
void glCallLogStart() {
    state().calls.clear();
    state().open = true;
    state().depth = 0;
}
std::vector<int> glCallLogStop() {
    state().open = false;
    return std::move(state().calls);
}
bool glCallLogEnter(int index) {
    State& s = state();
    if (!s.open) return false;
    if (s.depth == 0) s.calls.push_back(index);
    ++s.depth;
    return true;
}
void glCallLogLeave() {
    if (state().depth > 0) --state().depth;
}

} // namespace wb::ex
