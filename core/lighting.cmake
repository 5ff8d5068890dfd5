target_sources(core PRIVATE src/lighting.cpp)
