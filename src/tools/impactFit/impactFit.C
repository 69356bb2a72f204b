// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    impactFit

Description
    Coefficients of the Brach & Dunn model from measured normal impacts: the
    rebounds are split at -minSpeed (given, else chosen from the data so
    that each law has enough rebounds, the paper's 10 m/s when the data
    allow it); the restitution law is fitted (Levenberg-Marquardt) to the
    rebound ratio of the faster impacts, gamma recovered from each slower
    rebound with Eqs. 18 and 22 and the adhesion law fitted to it; then both
    laws are fitted together to every rebound (-noRefine: the paper's single
    pass). Each coefficient is printed with its standard error and 95 %
    interval (Student's t), each correlation coefficient with what it is
    computed over. See src/fitting/ImpactFit.H.

Usage
    \b impactFit -data FILE.csv [OPTIONS]

    Data: lines "diameter,speedIn,speedOut" (m, m/s, m/s; speedOut 0 for a
    captured particle); further columns are ignored (a row of more fields
    than a header of three or more names stops: a decimal comma), '#'
    starts a comment, a first line whose first field is not a number is a
    header; every other field must be a finite number, nothing else.

    Materials, from the adhesive entry of a case's cloud properties that
    applies to -patch NAME (-dict FILE, else the release's default file in
    constant/; read as impactCalc reads it) or from options:
      -rho VALUE, -particleE VALUE, -particleNu VALUE, -wallE VALUE,
      -wallNu VALUE (options override the dictionary)

    Options:
      -minSpeed VALUE          [m/s] (default: chosen from the data)
      -restitution powerLaw|constant
      -adhesion powerLaw|constant
      -noRefine                the paper's single pass
      -plot FILE.png           data against the fitted curves (gnuplot),
                               dashed where they extrapolate

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "caseWallModel.H"
#include "gnuplot.H"
#include "ImpactFit.H"

#include <fenv.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <tuple>

#include "impactFitInput.H"
#include "impactFitReport.H"

using namespace Foam;

namespace
{

//- The fit; an error of the data (a line, too few rebounds, all captured)
//  names the file, one of a setting its option
brachDunn::ImpactFitResult fit
(
    const fileName& dataFile,
    const std::vector<brachDunn::Measurement>& data,
    const brachDunn::ImpactFitSettings& s
)
{
    std::vector<std::pair<std::string, std::string>> optionOf
    {
        {"rho", "rho"}, {"restitution", "restitution"}, {"adhesion", "adhesion"}
    };
    if (s.minSpeed) optionOf.push_back({"minSpeed", "minSpeed"});
    return tools::coreCall
    (
        [&]
        {
            try
            {
                return brachDunn::fitImpacts(data, s);
            }
            catch (const brachDunn::InputError& err)
            {
                const std::string& k = err.keyword();
                if
                (
                    k.find("(line ") == std::string::npos
                 && k != "rebounds" && k != "speedOut"
                )
                {
                    throw;
                }
                FatalErrorInFunction
                    << dataFile.c_str() << ": " << err.what() << nl
                    << exit(FatalError);
                throw;
            }
        },
        optionOf
    );
}


} // End anonymous namespace


int main(int argc, char *argv[])
{
    addOptions();

    #include "setRootCase.H"

    // The fits mark rejected trial steps with infinite residuals: no
    // floating-point traps (OpenFOAM's FOAM_SIGFPE) here
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);

    if (tools::found(args, "plot"))
    {
        tools::checkPlotFile(tools::fileOption(args, "plot"));
    }
    const fileName dataFile(tools::fileOption(args, "data"));
    const std::vector<brachDunn::Measurement> data = readImpacts(dataFile);
    checkDiameters(args, dataFile, data);
    const brachDunn::ImpactFitSettings s = fitSettings(args);
    const brachDunn::ImpactFitResult result = fit(dataFile, data, s);

    printFit(std::cout, dataFile, data, result, s);
    if (tools::found(args, "plot"))
    {
        plot(tools::fileOption(args, "plot"), data, result, s);
    }
    return 0;
}
