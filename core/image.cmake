target_sources(core PRIVATE src/image.cpp)
