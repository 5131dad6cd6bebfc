// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The published coefficient tables, held once, as printed (natural units: ζ = β v^{1/5}).
//   [2008] T. Schwager, T. Pöschel, Phys. Rev. E 78, 051304 (2008), Tables III and V.
//   [1999] R. Ramírez, T. Pöschel, N. V. Brilliantov, T. Schwager, Phys. Rev. E 60, 4465 (1999),
//          Eqs. (31)-(36), Table I and Eqs. (A32)-(A36).
//   [2011] P. Müller, T. Pöschel, Phys. Rev. E 84, 021302 (2011), Padé approximants in sqrt(ζ) (as quoted
//          in the project's issue 3).
// docs/series.md lists the digits that disagree with the independent computation
// (restitution series certify).
#include <array>

namespace restitution::series::published {

// [2008] Table III, i = 1..10: τ_max = τ_max0 + Σ a_i ζ^i (time of maximal compression).
inline constexpr std::array<double, 10> kTable3A{
    -0.2867471220,  0.1048589922,    -0.04868406400, 0.02543116890,   -0.01423658282,
    0.008337660013, -0.005039737366, 0.003118137108, -0.001964027745, 0.001254701962};
// [2008] Table III, i = 0..10: x_max = Σ b_i ζ^i (maximal compression).
inline constexpr std::array<double, 11> kTable3B{1.093362074,   -0.5044548926,  0.2840430192,  -0.1702207776,
                                                 0.1055007088,  -0.06684871371, 0.04303949229, -0.02805108430,
                                                 0.01846085121, -0.01224618562, 0.008177589114};
// [2008] Table III, i = 1..10: ε_naive = 1 + Σ c_i ζ^i.
inline constexpr std::array<double, 10> kTable3C{-1.153448854,   0.7982665553, -0.5228825609, 0.3487426678,
                                                 -0.2330981260,  0.1566821477, -0.1058187828, 0.07176528242,
                                                 -0.04885717237, 0.03337347194};
// [2008] Table V, i = 0..20: ε_delayed = Σ h_i ζ^{i/2} (h_0 = 1).
inline constexpr std::array<double, 21> kTable5H{
    1.0,           0.0,           -1.153448856,  0.0,           0.7982665581,  0.2666666667,  -0.5228825657,
    -0.4613795424, 0.3487426737,  0.4523510496,  -0.1464314644, -0.3677282992, -0.0432489833, 0.2818042325,
    0.1478525872,  -0.1794420590, -0.1784660326, 0.06593358882, 0.1713586178,  0.0252498223,  -0.1379234986};

// Significant digits as printed (trailing zeros count): Table III prints every entry with 10; Table V
// mostly 10, h_12 and h_19 with 9, the exact h_0 = 1 and h_1 = h_3 = 0 with 1.
inline constexpr int kTable3Digits = 10;
inline constexpr std::array<int, 21> kTable5HDigits{1,  1, 10, 1,  10, 10, 10, 10, 10, 10, 10,
                                                    10, 9, 10, 10, 10, 10, 10, 10, 9,  10};

// [1999] Eq. (31): the numerical prefactor C1 of (g*)^{-1/5}, printed with six digits (closed form in
// Eq. (30): c1_closed_form() in series.hpp).
inline constexpr double kC1Eq31 = 1.15344;
// [1999] Eqs. (A32)-(A34) (convention ε = 1 + Σ C_k ζ^k): C1 ... C4.
inline constexpr std::array<double, 4> kAppendixC{-1.153449, 0.798267, -0.483582, 0.285279};
// [1999] Eqs. (A24)-(A27): y_0 ... y_3, the coefficients of x_max (the 2008 paper's b_0 ... b_3).
inline constexpr std::array<double, 4> kAppendixY{1.093362, -0.504455, 0.260542, -0.136769};
// [1999] Eqs. (33), (A35), (A36): a_k of the expansion in w = (g/g*)^{1/5}, ε = 1 - a1 w + a2 w² - a3 w³ + a4
// w⁴, a1 = 1 and a2 = 3/5 exact.
inline constexpr double kA3 = 0.315119;
inline constexpr double kA4 = 0.161167;
// [1999] Table I: the Padé [1/4] coefficients d_1 ... d_5 of Eq. (35) as printed.
inline constexpr std::array<double, 5> kTable1D{2.5839, 3.5839, 2.9839, 1.1487, 0.3265};

// [2011] Padé approximants in σ = sqrt(ζ), coefficients of ascending powers of σ.
inline constexpr std::array<double, 2> kPade2011Num14{1.0, 0.501086};
inline constexpr std::array<double, 5> kPade2011Den14{1.0, 0.501086, 1.15345, 0.577977, 0.532178};
inline constexpr std::array<double, 4> kPade2011Num36{1.0, 1.07232, 0.574198, 0.141552};
inline constexpr std::array<double, 7> kPade2011Den36{1.0,     1.07232,  1.72765, 1.37842,
                                                      1.19449, 0.467273, 0.235585};

}  // namespace restitution::series::published
