#pragma once
// Loading a texture image for lab 4 without ever failing hard: a missing, corrupt or
// absurdly large file gives a message naming the file and a procedural checkerboard.
#include "core/image.h"

#include <string>

namespace wb {

constexpr int kMaxTextureSide =
    4096; // larger files are refused (GL's guaranteed minimum is lower still)

// A width×height RGB checkerboard of `cell`-pixel squares (magenta/black, unmistakably a fallback).
Image checkerboard(int width, int height, int cell);

// Reads `path` as RGB into `out`. On failure `out` is a 64×64 checkerboard, `message`
// names the file and the reason, and the result is false. Never throws.
bool loadTextureImage(const std::string& path, Image& out, std::string& message);

} // namespace wb
