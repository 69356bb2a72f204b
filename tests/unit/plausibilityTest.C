// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Magnitudes that can only be unit mistakes stop with the value meant;
// values outside the model's range are warned about; extremeValues takes
// a mistake-looking value as it is. The bounds are the materials data of
// Plausibility.H (gelatin about 1e4 Pa, diamond 1.22e12 Pa, osmium 22590
// kg/m^3, aerosols 1 nm to 100 um (OpenFOAM's clouds up to centimetres),
// diamond's work of adhesion about 11
// J/m^2).

#include "Plausibility.H"

#include <gtest/gtest.h>

using namespace brachDunn;

namespace
{

//- The requirement of the InputError a value raises ("" when none)
std::string stops(const Magnitude& m, const std::string& keyword, double value)
{
    try
    {
        checkMagnitude(m, keyword, value);
        return "";
    }
    catch (const InputError& err)
    {
        EXPECT_EQ(err.keyword(), keyword);
        return err.what();
    }
}

bool has(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // End anonymous namespace


TEST(Plausibility, YoungsModulusTypedInGPa)
{
    const std::string steel = stops(magnitude::youngsModulus, "E", 320);
    EXPECT_TRUE(has(steel, "E = 320: a Young's modulus in Pa; 320 Pa is softer"
        " than any solid this model describes; did you mean 3.2e+11 (320 GPa)?"))
        << steel;
    EXPECT_TRUE(has(stops(magnitude::youngsModulus, "E", 70), "7e+10 (70 GPa)"));
    // A polymer typed in MPa: GPa would be stiffer than diamond
    EXPECT_TRUE(has(stops(magnitude::youngsModulus, "E", 2500), "2.5e+09 (2500 MPa)"));
    // Stiffer than diamond
    EXPECT_TRUE(has(stops(magnitude::youngsModulus, "E", 3.2e14), "stiffer than any solid"));
    // The bounds
    EXPECT_EQ(stops(magnitude::youngsModulus, "E", 1e4), "");
    EXPECT_NE(stops(magnitude::youngsModulus, "E", 9.9e3), "");
    EXPECT_EQ(stops(magnitude::youngsModulus, "E", 1.22e12), "");
}


TEST(Plausibility, PhysicalButOutsideTheModelWarns)
{
    // Steel typed in MPa is an elastomer's modulus: no check can tell
    EXPECT_EQ(stops(magnitude::youngsModulus, "E", 2.1e5), "");
    EXPECT_TRUE(has(checkMagnitude(magnitude::youngsModulus, "E", 2.1e5),
                    "outside the range the model was made for"));
    EXPECT_EQ(checkMagnitude(magnitude::youngsModulus, "E", 3.2e11), "");
    EXPECT_TRUE(has(checkMagnitude(magnitude::diameter, "d", 2e-3), "outside"));
    EXPECT_EQ(checkMagnitude(magnitude::diameter, "d", 5e-6), "");
    // No adhesion is not a small one
    EXPECT_EQ(checkMagnitude(magnitude::surfaceEnergy, "gamma", 0), "");
    EXPECT_TRUE(has(checkMagnitude(magnitude::surfaceEnergy, "gamma", 1e-4), "outside"));
}


TEST(Plausibility, DensityDiameterAndSurfaceEnergy)
{
    EXPECT_TRUE(has(stops(magnitude::density, "rho0", 1.35), "1350 (1.35 g/cm^3)"));
    EXPECT_TRUE(has(stops(magnitude::density, "rho0", 25000), "denser than any material"));
    EXPECT_EQ(stops(magnitude::density, "rho0", 25), "");
    EXPECT_TRUE(has(stops(magnitude::diameter, "d", 5), "5e-06 (5 um)"));
    EXPECT_TRUE(has(stops(magnitude::diameter, "d", 1e-10), "smaller than any particle"));
    // millimetre to centimetre particles of coal, sprays and beds are real
    // (v1912's reactingHeterogenousParcelFoam tutorial: 11 mm); sub-micron
    // sizes typed in um are not (0.1 um typed 0.1: 10 cm; 0.02 um: 2 cm)
    EXPECT_EQ(stops(magnitude::diameter, "d", 0.011), "");
    EXPECT_EQ(stops(magnitude::diameter, "d", 0.015), "");
    EXPECT_NE(stops(magnitude::diameter, "d", 0.0151), "");
    EXPECT_TRUE(has(stops(magnitude::diameter, "d", 0.1), "1e-07 (0.1 um)"));
    EXPECT_NE(stops(magnitude::diameter, "d", 0.02), "");
    EXPECT_NE(stops(magnitude::diameter, "d", 0.5), "");
    // a suggestion beyond the doubles is no suggestion, and no crash
    EXPECT_NE(stops(magnitude::diameter, "d", 1e-300), "");
    EXPECT_TRUE(has(stops(magnitude::surfaceEnergy, "gamma", 50), "0.05 (50 mJ/m^2)"));
    EXPECT_EQ(stops(magnitude::surfaceEnergy, "gamma", 15), "");
    // No unit mistake below: a negative surface energy is left to the
    // caller's sign check (no message with the reason missing)
    EXPECT_EQ(unitMistake(magnitude::surfaceEnergy, "w", -1), "");
}


TEST(Plausibility, ExtremeValuesTakesTheValue)
{
    const std::string w = checkMagnitude(magnitude::youngsModulus, "E", 320, true);
    EXPECT_TRUE(has(w, "did you mean 3.2e+11")) << w;
    EXPECT_TRUE(has(w, "taken as given")) << w;
}


TEST(Plausibility, TheValueMeantIsTheDecimalOne)
{
    // 4.9 um is 4.9e-06 m, not 4.9/1e6; values written with an exponent too
    EXPECT_TRUE(has(stops(magnitude::diameter, "d", 4.9), "4.9e-06 (4.9 um)"));
    EXPECT_TRUE(has(stops(magnitude::youngsModulus, "E", 2e-2), "2e+07 (0.02 GPa)"));
    EXPECT_TRUE(has(stops(magnitude::surfaceEnergy, "gamma", 1.5e2), "0.15 (150 mJ/m^2)"));
}


TEST(Plausibility, AnAmbiguousDiameterNamesBothUnits)
{
    // 150 is 1.5e-4 m in um (a physical diameter beyond the model's range,
    // and the likelier unit) or 1.5e-7 m in nm (inside it): both are named,
    // the likelier first
    EXPECT_TRUE(has(stops(magnitude::diameter, "maxDiameter", 150),
        "did you mean 0.00015 (150 um) or 1.5e-07 (150 nm)?"))
        << stops(magnitude::diameter, "maxDiameter", 150);
    // Where the likelier unit lands in the model's range, it alone
    EXPECT_TRUE(has(stops(magnitude::diameter, "d", 20), "did you mean 2e-05 (20 um)?"));
    EXPECT_TRUE(has(stops(magnitude::youngsModulus, "E", 320), "did you mean 3.2e+11 (320 GPa)?"));
}


TEST(Plausibility, TheGasState)
{
    // A temperature typed in degrees Celsius (an offset, not a power of
    // ten): 20 degC is 293.15 K
    EXPECT_TRUE(has(stops(magnitude::temperature, "T", 20),
        "T = 20: a gas temperature in K; 20 K is colder than any gas carrying"
        " aerosols (air liquefies at 79-82 K); did you mean 293.15 (20 degC)?"))
        << stops(magnitude::temperature, "T", 20);
    EXPECT_EQ(stops(magnitude::temperature, "T", 293.15), "");
    // The sum in decimal (not the binary 294.84999999999997), and 0 or
    // below typed in degC too
    EXPECT_TRUE(has(stops(magnitude::temperature, "T", 21.7), "did you mean 294.85 (21.7 degC)?"))
        << stops(magnitude::temperature, "T", 21.7);
    EXPECT_TRUE(has(stops(magnitude::temperature, "T", 0), "did you mean 273.15 (0 degC)?"));
    EXPECT_TRUE(has(stops(magnitude::temperature, "T", -10), "did you mean 263.15 (-10 degC)?"));
    EXPECT_EQ(stops(magnitude::temperature, "T", 100), "");
    EXPECT_NE(stops(magnitude::temperature, "T", 99), "");
    EXPECT_NE(stops(magnitude::temperature, "T", 2e4), "");
    // The atmosphere in bar or in kPa: both landing in the range, both named
    EXPECT_TRUE(has(stops(magnitude::pressure, "p", 1.01325),
        "did you mean 101325 (1.01325 bar) or 1013.25 (1.01325 kPa)?"))
        << stops(magnitude::pressure, "p", 1.01325);
    // The unit that gives the nearest to an atmosphere first
    EXPECT_TRUE(has(stops(magnitude::pressure, "p", 101.325),
        "did you mean 101325 (101.325 kPa) or 10132500 (101.325 bar)?"))
        << stops(magnitude::pressure, "p", 101.325);
    EXPECT_TRUE(has(stops(magnitude::pressure, "p", 0.101325),
        "did you mean 101325 (0.101325 MPa) or 10132.5 (0.101325 bar)?"))
        << stops(magnitude::pressure, "p", 0.101325);
    EXPECT_EQ(stops(magnitude::pressure, "p", 101325), "");
    EXPECT_EQ(stops(magnitude::pressure, "p", 1e3), "");
    EXPECT_NE(stops(magnitude::pressure, "p", 999), "");
    EXPECT_NE(stops(magnitude::pressure, "p", 2e8), "");
    // Air's mean free path at 1 atm, 66.5 nm, typed in nm or um
    EXPECT_TRUE(has(stops(magnitude::meanFreePath, "meanFreePath", 66.5),
        "did you mean 6.65e-08 (66.5 nm)?"));
    EXPECT_TRUE(has(stops(magnitude::meanFreePath, "meanFreePath", 0.0665),
        "did you mean 6.65e-08 (0.0665 um)?"));
    EXPECT_EQ(stops(magnitude::meanFreePath, "meanFreePath", 66.5e-9), "");
    EXPECT_NE(stops(magnitude::meanFreePath, "meanFreePath", 2e-5), "");
    // Air's molar mass typed in g/mol
    EXPECT_TRUE(has(stops(magnitude::molarMass, "molarMass", 28.96),
        "did you mean 0.02896 (28.96 g/mol)?"));
    EXPECT_EQ(stops(magnitude::molarMass, "molarMass", 0.0289647), "");
    // None of them warns inside its physical range (no model's range)
    EXPECT_EQ(checkMagnitude(magnitude::temperature, "T", 150), "");
    EXPECT_EQ(checkMagnitude(magnitude::pressure, "p", 5e7), "");
}


TEST(Plausibility, TheCallerSaysHowToTakeAValueAsGiven)
{
    // The core's message ends where the caller's hint goes (here at the
    // value meant): the keyword or option that takes the value as given is
    // the adapter's and the tools' to name
    const std::string e = stops(magnitude::youngsModulus, "E", 320);
    ASSERT_FALSE(e.empty());
    EXPECT_EQ(e.back(), '?') << e;
    EXPECT_FALSE(has(e, "extremeValues")) << e;
}
