// xkb-lock-group N: makes keyboard group (layout) N the active one on $DISPLAY, as a user's
// layout switch does, and prints it. The layout tests (tests/shell/russian_keys.sh) lock the
// Russian group of `setxkbmap -layout us,ru` and then press physical keys with xdotool.
#include <X11/XKBlib.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s GROUP (0 = first layout)\n", argv[0]);
        return 2;
    }
    int major = XkbMajorVersion, minor = XkbMinorVersion, error = 0;
    Display* d = XkbOpenDisplay(nullptr, nullptr, nullptr, &major, &minor, &error);
    if (!d) {
        std::fprintf(stderr, "%s: cannot open the display with XKB\n", argv[0]);
        return 1;
    }
    if (!XkbLockGroup(d, XkbUseCoreKbd, unsigned(std::atoi(argv[1]))))
        std::fprintf(stderr, "lock failed\n");
    XSync(d, False);
    XkbStateRec s{};
    XkbGetState(d, XkbUseCoreKbd, &s);
    std::printf("group %d\n", int(s.group));
    XCloseDisplay(d);
    return 0;
}
