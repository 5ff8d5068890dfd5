#include "test_lab.h"

#include "common/gl.h"

#include <imgui.h>

namespace wb::test {
namespace {
class TestLab : public Lab {
public:
    explicit TestLab(TestLabState* s) : s_(s ? s : &own_) {}
    std::string title() const override { return "Test lab"; }
    std::vector<KeyHelp> keys() const override { return {{"g", "green triangle"}}; }
    void init() override { ++s_->initCalls; }
    void draw(const View&) override {
        ++s_->frames;
        glClearColor(0, ranFrames_ >= kRunFrames ? 0.5f : 0.f, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        if (running_) // yellow while running; the run ends as this frame is drawn
            glColor3f(1.f, 1.f, 0.f);
        else
            glColor3f(s_->green ? 0.f : 1.f, s_->green ? 1.f : 0.f, 0.f);
        glBegin(GL_TRIANGLES); // covers the lower-left half of the viewport
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(-1, 1);
        glEnd();
        if (running_ && ++ranFrames_ >= kRunFrames) running_ = false; // after the drawing
    }
    bool key(int k) override {
        if (k == 'L') {
            s_->longLabel = !s_->longLabel;
            return true;
        }
        if (k == 'B') {
            running_ = true;
            ranFrames_ = 0;
            return true;
        }
        if (k == 'F') { // the headless render must then be neither written nor exit 0
            failed_ = true;
            return true;
        }
        if (k != 'g') return false;
        s_->green = !s_->green;
        return true;
    }
    void gui() override {
        if (ImGui::Button("Press me")) ++s_->presses;
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        s_->buttonX = 0.5f * (a.x + b.x);
        s_->buttonY = 0.5f * (a.y + b.y);
        if (!s_->longLabel) return;
        ImGui::SliderFloat("a label far too long to fit beside its slider in any panel", &value_, 0, 1);
        for (int i = 0; i < 60; ++i) ImGui::Text("line %d", i); // taller than the window: it scrolls
    }
    bool busy() const override { return s_->frames < 3 || running_; }
    bool headlessFailed() const override { return failed_; }

private:
    bool failed_ = false;
    static constexpr int kRunFrames = 12; // past the frames drawn after start-up events
    bool running_ = false;                // `B`
    int ranFrames_ = 0;
    TestLabState own_;
    float value_ = 0.5f;
    TestLabState* s_;
};
} // namespace

std::unique_ptr<Lab> makeTestLab(TestLabState* observe) { return std::make_unique<TestLab>(observe); }

} // namespace wb::test
