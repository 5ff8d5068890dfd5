target_sources(core PRIVATE src/image.cpp)
# issue 12: user-named files read whole with a size cap, regular files only
target_sources(core PRIVATE src/file_read.cpp)
