// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    impactFit

Description
    Coefficients of the Brach & Dunn model from measured normal impacts: the
    restitution law fitted (Levenberg-Marquardt) to the rebound ratio of the
    impacts faster than -minSpeed, gamma recovered from each slower rebound
    with Eqs. 18 and 22 and the adhesion law fitted to it; refined until the
    fast impacts' own adhesion is accounted for (-noRefine: the paper's
    single pass). See src/fitting/ImpactFit.H.

Usage
    \b impactFit -data FILE.csv [OPTIONS]

    Data: lines "diameter,speedIn,speedOut" (m, m/s, m/s; speedOut 0 for a
    captured particle); further columns are ignored, '#' starts a comment, a
    first line whose first field is not a number is a header; every other
    field must be a finite number, nothing else.

    Materials, from the adhesive entry of a case's cloud properties that
    applies to -patch NAME (-dict FILE, else the release's default file in
    constant/; read as impactCalc reads it) or from options:
      -rho VALUE, -particleE VALUE, -particleNu VALUE, -wallE VALUE,
      -wallNu VALUE (options override the dictionary)

    Options:
      -minSpeed VALUE          [m/s] (default 10, as the paper)
      -restitution powerLaw|constant
      -adhesion powerLaw|constant
      -noRefine                the paper's single pass
      -plot FILE.png           data against the fitted curves (gnuplot)

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

using namespace Foam;

namespace
{

//- The measured impacts of a CSV file
std::vector<brachDunn::Measurement> readImpacts(const fileName& file)
{
    std::ifstream in(file);
    if (!isFile(file) || !in.good())
    {
        FatalErrorInFunction
            << "Option -data " << file.c_str() << ": cannot read this file"
            << nl << exit(FatalError);
    }
    std::vector<brachDunn::Measurement> data;
    std::string text;
    int line = 0;
    bool first = true;
    while (std::getline(in, text))
    {
        ++line;
        text = text.substr(0, text.find('#'));
        if (text.find_first_not_of(" \t\r,") == std::string::npos) continue;

        // The first three comma-separated fields, each a number and only that
        std::vector<std::string> fields;
        std::istringstream columns(text);
        for (std::string field; fields.size() < 3 && std::getline(columns, field, ',');)
        {
            const auto begin = field.find_first_not_of(" \t\r");
            const auto end = field.find_last_not_of(" \t\r");
            fields.push_back
            (
                begin == std::string::npos ? "" : field.substr(begin, end - begin + 1)
            );
        }
        scalar values[3] = {0, 0, 0};
        bool good = fields.size() == 3;
        for (std::size_t i = 0; good && i < 3; ++i)
        {
            good = tools::parseNumber(fields[i], values[i]);
        }
        if (!good)
        {
            // A header: a first line whose first field is not a number
            scalar number = 0;
            if (first && !tools::parseNumber(fields[0], number))
            {
                first = false;
                continue;
            }
            FatalErrorInFunction
                << file.c_str() << " line " << line << ": expected"
                << " diameter,speedIn,speedOut, each a finite number, found '"
                << text.c_str() << "'" << nl << exit(FatalError);
        }
        first = false;
        data.push_back({values[0], values[1], values[2], line});
    }
    if (data.empty())
    {
        FatalErrorInFunction
            << "Option -data " << file.c_str() << ": no impacts in this file"
            << nl << exit(FatalError);
    }
    return data;
}


//- The value of an option, else of the case's material, else an error
scalar materialValue
(
    const argList& args,
    const word& option,
    const std::optional<scalar>& fromCase
)
{
    if (tools::found(args, option)) return tools::number(args, option);
    if (fromCase) return *fromCase;
    FatalErrorInFunction
        << "Option -" << option << " is required (or -patch, whose entry"
        << " gives the materials)" << nl << exit(FatalError);
    return 0;
}


void printFit(std::ostream& os, const brachDunn::LawFit& fit, const char* unit)
{
    for (std::size_t i = 0; i < fit.values.size(); ++i)
    {
        os  << "    " << std::left << std::setw(6) << fit.names[i]
            << std::setprecision(5) << fit.values[i] << " +- "
            << std::setprecision(2) << fit.standardErrors[i]
            << (fit.names[i] == "c" || fit.names[i] == "gamma" ? unit : "")
            << '\n';
    }
    os  << "    correlation coefficient " << std::setprecision(4)
        << fit.correlation << ", " << fit.points << " impacts\n";
}


//- The data and the fitted curves, by diameter
void plot
(
    const fileName& png,
    const std::vector<brachDunn::Measurement>& data,
    const brachDunn::ImpactFitResult& fit,
    const brachDunn::ImpactFitSettings& s
)
{
    const brachDunn::ImpactModel model = brachDunn::fittedModel(fit, s);
    std::vector<double> diameters;
    for (const auto& m : data)
    {
        if (std::find(diameters.begin(), diameters.end(), m.d) == diameters.end())
        {
            diameters.push_back(m.d);
        }
    }
    std::vector<tools::plotSeries> series;
    for (std::size_t i = 0; i < diameters.size(); ++i)
    {
        const double d = diameters[i];
        std::ostringstream measured, colour;
        measured << d << " m, measured";
        colour << " lc " << i + 1;
        series.push_back({measured.str(), "points pt 7" + colour.str(), {}});
        for (const auto& m : data)
        {
            if (m.d == d) series.back().points.push_back({m.speedIn, m.speedOut/m.speedIn});
        }
        series.push_back({"fitted", "lines" + colour.str(), {}});
        for (int j = 0; j <= 200; ++j)
        {
            const double v = 0.1*std::pow(2000.0, j/200.0);
            const auto r = model.impact(brachDunn::Particle{d, s.rho}, v, 0);
            series.back().points.push_back({v, r.captured() ? 0 : r.unOut/v});
        }
    }
    std::ostringstream settings;
    settings
        << "set logscale x\nset grid\nset key outside right\n"
        << "set yrange [0:1.05]\n"
        << "set xlabel 'incoming normal speed [m/s]'\n"
        << "set ylabel 'rebound ratio Un''/un'\n"
        << "set arrow from " << s.minSpeed << ", graph 0 to " << s.minSpeed
        << ", graph 1 nohead dashtype 2\n";
    tools::plot(png, series, settings.str());
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Fit the restitution and adhesion laws of the Brach & Dunn model to"
        " measured normal impacts"
    );
    tools::addCaseOptions("patch entry giving the materials");
    argList::addOption("data", "file", "CSV of diameter,speedIn,speedOut");
    argList::addOption("particleE", "value", "particle Young's modulus [Pa]");
    argList::addOption("particleNu", "value", "particle Poisson's ratio");
    argList::addOption("wallE", "value", "wall Young's modulus [Pa]");
    argList::addOption("wallNu", "value", "wall Poisson's ratio");
    argList::addOption("minSpeed", "value", "fast/slow split [m/s] (10)");
    argList::addOption("restitution", "type", "powerLaw (default) or constant");
    argList::addOption("adhesion", "type", "powerLaw (default) or constant");
    argList::addBoolOption("noRefine", "the paper's single pass");
    argList::addOption("plot", "file.png", "plot data and fits");

    #include "setRootCase.H"

    // The fits mark rejected trial steps with infinite residuals: no
    // floating-point traps (OpenFOAM's FOAM_SIGFPE) here
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);

    const fileName dataFile(tools::fileOption(args, "data"));
    const std::vector<brachDunn::Measurement> data = readImpacts(dataFile);

    // Materials from the case's adhesive entry when -patch is given;
    // options override
    std::optional<brachDunn::ElasticMaterial> particle, wall;
    std::optional<scalar> rho;
    if (tools::found(args, "patch"))
    {
        const word patchName(tools::text(args, "patch"));
        const tools::caseWallModel wallModel(args, patchName);
        const wallInteractionEntry& entry = wallModel.entry();
        if (entry.type() != wallInteractionEntry::interaction::adhesive)
        {
            FatalErrorInFunction
                << "Patch " << patchName << " is of type " << entry.typeName()
                << ", not adhesive: it has no wall material" << nl
                << exit(FatalError);
        }
        particle = entry.model().particleMaterial();
        wall = entry.model().wallMaterial();
        rho = wallModel.particleDensity(args);
    }
    const auto part = [](const auto& material, scalar brachDunn::ElasticMaterial::*member)
    {
        return material ? std::optional<scalar>((*material).*member) : std::nullopt;
    };
    brachDunn::ImpactFitSettings s;
    s.particle.E = materialValue(args, "particleE", part(particle, &brachDunn::ElasticMaterial::E));
    s.particle.nu = materialValue(args, "particleNu", part(particle, &brachDunn::ElasticMaterial::nu));
    s.wall.E = materialValue(args, "wallE", part(wall, &brachDunn::ElasticMaterial::E));
    s.wall.nu = materialValue(args, "wallNu", part(wall, &brachDunn::ElasticMaterial::nu));
    s.rho = materialValue(args, "rho", rho);
    s.minSpeed = tools::number(args, "minSpeed", 10);
    s.restitutionType = tools::wordOption(args, "restitution", "powerLaw");
    s.adhesionType = tools::wordOption(args, "adhesion", "powerLaw");
    s.refine = !tools::found(args, "noRefine");
    tools::coreCall
    (
        [&]{ s.particle.check(); }, {{"E", "particleE"}, {"nu", "particleNu"}}
    );
    tools::coreCall
    (
        [&]{ s.wall.check(); }, {{"E", "wallE"}, {"nu", "wallNu"}}
    );

    // An error of a data line names the file; one of a setting its option
    const brachDunn::ImpactFitResult fit = tools::coreCall
    (
        [&]
        {
            try
            {
                return brachDunn::fitImpacts(data, s);
            }
            catch (const brachDunn::InputError& err)
            {
                if (err.keyword().find("(line ") == std::string::npos)
                {
                    throw;
                }
                FatalErrorInFunction
                    << dataFile.c_str() << ' ' << err.what() << nl
                    << exit(FatalError);
                throw;
            }
        },
        {
            {"rho", "rho"}, {"minSpeed", "minSpeed"},
            {"restitution", "restitution"}, {"adhesion", "adhesion"}
        }
    );

    std::ostream& os = std::cout;
    os  << "impactFit: " << data.size() << " impacts from " << dataFile.c_str()
        << " (" << fit.captured << " captured, left out of the fits)\n"
        << "particle E " << s.particle.E << " Pa, nu " << s.particle.nu
        << ", rho " << s.rho << " kg/m^3; wall E " << s.wall.E << " Pa, nu "
        << s.wall.nu << "\n\n"
        << "Restitution (" << fit.restitution.type
        << (s.refine ? ", joint fit below); correlation over" : ") from")
        << " the impacts faster than " << s.minSpeed << " m/s:\n";
    printFit(os, fit.restitution, "");
    os  << "Adhesion (" << fit.adhesion.type << ", gamma in J/m^2, un in m/s"
        << (s.refine ? ", joint fit below); correlation over" : ") from")
        << " the rebounds at or below " << s.minSpeed << " m/s:\n";
    printFit(os, fit.adhesion, " J/m^2");
    os  << (s.refine
          ? "Refined: both laws fitted together to every rebound, from "
          + std::to_string(fit.iterations) + " alternating passes.\n"
          : std::string("Single pass (-noRefine): the fast impacts taken as"
            " free of adhesion.\n"))
        << "\nFor the patch entry of adhesiveWallInteractionCoeffs:\n"
        << "    restitution " << fit.restitution.dictionary() << '\n'
        << "    adhesion    " << fit.adhesion.dictionary() << '\n';

    if (tools::found(args, "plot"))
    {
        plot(tools::fileOption(args, "plot"), data, fit, s);
    }
    return 0;
}
