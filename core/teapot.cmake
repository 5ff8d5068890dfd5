# The Utah teapot from Newell's 32 Bezier patches (issue 11), evaluated with core/bezier.
target_sources(core PRIVATE src/teapot.cpp)
