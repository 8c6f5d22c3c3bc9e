// Material files (`--material FILE`): what the stock is made of,
// as text, into a StockComposition (core/material/material.h). One statement
// a line; '#' starts a comment; words are separated by blanks; lengths in
// millimetres, machine coordinates; names up to 16 characters.
//
//   preset NAME                      start from a built-in preset (two-layer,
//                                    marble, wood, bronze, aluminium,
//                                    wood-on-aluminium, ...) on the stock
//   material NAME TEXTURE [KEY=VALUE ...]
//        TEXTURE: plain, layers, marble, wood, bronze, granite
//        colour=R,G,B         plain: the colour; marble: the base; wood: the
//                             light wood; bronze: the base; granite: the base
//        vein=R,G,B           marble: the veins; wood: the dark rings
//        period=MM            marble: vein spacing; wood: ring pitch
//        seed=N               the texture's noise seed
//        max_feed=MM/MIN      the fastest feed it may be cut at
//        spindle=MIN..MAX     the spindle speeds it may be cut at (rpm)
//        coolant=yes|no       whether M7/M8 may be on while cutting it
//        tolerance=MM         the accuracy its faces need
//        density=G/CM3        for the mass removed
//        kc1.1=N/MM2, mc=X    Kienzle's cutting coefficients: force, torque, power
//        max_chip=MM          the thickest chip a tooth may take (--check load)
//   layer Z0 Z1 NAME                 Z0 <= z < Z1 is NAME
//   box X0,Y0,Z0,X1,Y1,Z1 NAME       an insert (later ones win)
//   cylinder X,Y,R,Z0,Z1 NAME        a vertical cylindrical insert
//   default NAME                     what fills the rest (default: the
//                                    first material)
//
// Errors are "FILE:LINE:COL: error: MESSAGE" (the column of the word at
// fault); nothing of a file with an error is used.
#ifndef DEXMILL_PLATFORM_FORMAT_MATERIAL_FILE_H
#define DEXMILL_PLATFORM_FORMAT_MATERIAL_FILE_H

#include <cstddef>
#include <string>

#include "core/material/material.h"
#include "core/point.h"

namespace dexmill {

// The largest material file read (a real one is a few hundred bytes).
constexpr std::size_t kMaterialFileMaxBytes = std::size_t{1} << 20;

// Parses text[0, n) named `name` (for messages) for a stock box `stock`
// (the presets' placement). On failure *err holds the whole error line and
// *out is unchanged.
bool material_file_parse(const char* name, const char* text, std::size_t n, const BoxNm& stock,
                         StockComposition* out, std::string* err);

// Reads and parses the file at `path`: kIoError when it cannot be read,
// kInputError when it is too large or wrong (*err the whole message).
enum class MaterialLoad : uint8_t { kOk, kIoError, kInputError };
MaterialLoad material_file_load(const std::string& path, const BoxNm& stock, StockComposition* out, std::string* err);

}  // namespace dexmill

#endif
