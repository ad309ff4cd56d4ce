#pragma once
// Every limit stencilgen puts on its input, in one place (README: "What
// stencilgen refuses, and why"). Each bounds the work or memory that a small
// input could otherwise ask for, or keeps a number inside the range of the
// integer type that holds it; each error that enforces one names the limit.

namespace sg::limits {

// Rates n (--n, plot --n, "n" of a table given to verify). A curve table at
// n = 4096 takes seconds; a surface table's stencils grow with n^2 (quad
// n = 128 at valence 8: 2 s and 6.5 MB of JSON).
inline constexpr long kMaxCurveRate = 4096;
// The exact numbers of one curve run, in decimal digits (about the bytes of its
// JSON tables; verify reads table files up to 1 GiB). The size of a curve
// table depends on the rate's arithmetic, not only its size: fourpoint at
// n = 4096 is 2.6 MB, at n = 4093 (2 has order 4092 mod 4093) 290 MB, and
// every rate 1..4096 would be over 100 GB. Rates run largest first and the
// run stops, naming this limit, once its tables pass it.
inline constexpr long kMaxCurveRunDigits = 1L << 30;
inline constexpr long kMaxSurfaceRate = 128;  // quad and triangle schemes

// Valences (--valence, a scheme's "valences", a table's "valence"). The runtime
// takes the same range; a scheme file may declare a narrower one.
inline constexpr int kMinValence = 3;
inline constexpr int kMaxValence = 64;

// analyze --samples: the characteristic map is sampled on the patch grid
// 1/samples, the grid of a table at rate samples / 2.
inline constexpr long kMaxAnalysisSamples = 2 * kMaxSurfaceRate;

// Formulas (scheme files, --param). The parser recurses once per level of
// parentheses, signs and powers; exponents and intermediate results are
// bounded so that ((2^4096)^4096)^4096 is refused instead of computed.
inline constexpr long kMaxExpressionLength = 4096;  // characters
inline constexpr int kMaxExpressionDepth = 64;      // nested levels
inline constexpr long kMaxExponent = 4096;          // |e| in x^e
inline constexpr long kMaxExpressionBits = 65536;   // numerator + denominator of any intermediate value

// JSON documents (scheme files, tables given to verify): nesting is checked
// while parsing, before anything walks the document recursively.
inline constexpr int kMaxJsonDepth = 32;
inline constexpr long kMaxSchemeFileBytes = 1L << 20;  // 1 MiB
inline constexpr long kMaxTableFileBytes = 1L << 30;   // 1 GiB (the largest tables within the rate limits are far smaller)

// Curve masks: the supports, and with them every grid the solvers build, stay small.
inline constexpr long kMaxMaskLength = 64;        // coefficients of a mask or special column
inline constexpr long kMaxMaskOffset = 64;        // |first| of a mask, |index| of a special column
inline constexpr long kMaxSpecialColumns = 64;
inline constexpr int kMinKnotDegree = 1;
inline constexpr int kMaxKnotDegree = 15;

// Names: a scheme's name is a file name (OUT/<name>/, <name>.sgs) and a
// table's "scheme" is looked up as one; parameters are names in formulas.
inline constexpr long kMaxNameLength = 64;
// Scheme names: letters, digits, '-', '_' and '.', starting with a letter or digit.
// Parameter names: letters, digits and '_', starting with a letter or '_'.

}  // namespace sg::limits
