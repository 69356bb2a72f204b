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
    first line that is not numbers is a header.

    Materials, from a case's cloud properties (-dict FILE or the case's
    constant/kinematicCloudProperties, with -patch NAME) or from options:
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
#include "cloudPatchModel.H"
#include "gnuplot.H"
#include "ImpactFit.H"
#include "OSspecific.H"

#include <fenv.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

using namespace Foam;

namespace
{

//- The measured impacts of a CSV file
std::vector<brachDunn::Measurement> readImpacts(const fileName& file)
{
    std::ifstream in(file);
    if (!in.good())
    {
        FatalErrorInFunction << "Cannot read the data file " << file.c_str() << nl
            << exit(FatalError);
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

        std::replace(text.begin(), text.end(), ',', ' ');
        std::istringstream fields(text);
        brachDunn::Measurement m;
        m.line = line;
        if (!(fields >> m.d >> m.speedIn >> m.speedOut))
        {
            // A header: a first line that does not start with a number
            std::istringstream start(text);
            double number;
            if (first && !(start >> number)) { first = false; continue; }
            FatalErrorInFunction
                << file.c_str() << " line " << line << ": expected"
                << " diameter,speedIn,speedOut numbers" << nl
                << exit(FatalError);
        }
        first = false;
        data.push_back(m);
    }
    if (data.empty())
    {
        FatalErrorInFunction << "No impacts in " << file.c_str() << nl
            << exit(FatalError);
    }
    return data;
}


//- The value of an option, else of the material, else an error
scalar materialValue
(
    const argList& args,
    const word& option,
    const scalar* fromDict
)
{
    if (tools::found(args, option)) return tools::number(args, option);
    if (fromDict) return *fromDict;
    FatalErrorInFunction
        << "Option -" << option << " is required (or -dict/-patch giving"
        << " the materials)" << nl << exit(FatalError);
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


void plot
(
    const fileName& png,
    const std::vector<brachDunn::Measurement>& data,
    const brachDunn::ImpactFitResult& fit,
    const brachDunn::ImpactFitSettings& s
)
{
    const fileName dataFile = png.lessExt() + ".dat";
    const brachDunn::ImpactModel model
    (
        s.particle, s.wall,
        brachDunn::RestitutionLaw::select
        (
            fit.restitution.type,
            brachDunn::MapParameters
            (
                fit.restitution.type == "powerLaw"
              ? brachDunn::MapParameters
                {{"k", fit.restitution.values[0]}, {"p", fit.restitution.values[1]}}
              : brachDunn::MapParameters{{"R", fit.restitution.values[0]}}
            )
        ),
        fit.adhesion.type == "powerLaw"
      ? brachDunn::AdhesionLaw::powerLaw
        (
            fit.adhesion.values[0], std::max(fit.adhesion.values[1], 0.0)
        )
      : brachDunn::AdhesionLaw::constant(std::max(fit.adhesion.values[0], 0.0)),
        brachDunn::FrictionLaw::sticking(), -1, 0
    );

    // Diameters measured, each a data series and a fitted curve
    std::vector<double> diameters;
    for (const auto& m : data)
    {
        if (std::find(diameters.begin(), diameters.end(), m.d) == diameters.end())
        {
            diameters.push_back(m.d);
        }
    }
    std::ofstream out(dataFile);
    out << std::setprecision(8);
    for (const double d : diameters)
    {
        for (const auto& m : data)
        {
            if (m.d == d) out << m.speedIn << ' ' << m.speedOut/m.speedIn << '\n';
        }
        out << "\n\n";
        for (int i = 0; i <= 200; ++i)
        {
            const double v = 0.1*std::pow(2000.0, i/200.0);
            const auto r = model.impact(brachDunn::Particle{d, s.rho}, v, 0);
            out << v << ' ' << (r.captured() ? 0 : r.unOut/v) << '\n';
        }
        out << "\n\n";
    }
    out.close();

    std::ostringstream gp;
    gp  << "set logscale x\nset grid\nset key outside right\n"
        << "set yrange [0:1.05]\n"
        << "set xlabel 'incoming normal speed [m/s]'\n"
        << "set ylabel 'rebound ratio Un''/un'\n"
        << "set arrow from " << s.minSpeed << ", graph 0 to " << s.minSpeed
        << ", graph 1 nohead dashtype 2\n"
        << "plot";
    for (std::size_t i = 0; i < diameters.size(); ++i)
    {
        gp  << (i ? ", \\\n    " : " ")
            << "'" << dataFile.c_str() << "' index " << 2*i
            << " using 1:2 with points pt 7 lc " << i + 1 << " title '"
            << diameters[i] << " m, measured', '" << dataFile.c_str()
            << "' index " << 2*i + 1 << " using 1:2 with lines lc " << i + 1
            << " title 'fitted'";
    }
    gp << '\n';
    tools::gnuplot(png, gp.str());
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Fit the restitution and adhesion laws of the Brach & Dunn model to"
        " measured normal impacts"
    );
    argList::noParallel();
    compat::noBanner();
    argList::addOption("data", "file", "CSV of diameter,speedIn,speedOut");
    argList::addOption("dict", "file", "cloud properties giving the materials");
    argList::addOption("patch", "name", "patch entry giving the wall material");
    argList::addOption("rho", "value", "particle density [kg/m^3]");
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

    const fileName dataFile(tools::text(args, "data"));
    const std::vector<brachDunn::Measurement> data = readImpacts(dataFile);

    // Materials from the dictionary when given, options override
    brachDunn::ImpactFitSettings s;
    std::unique_ptr<brachDunn::ElasticMaterial> particleDict, wallDict;
    std::unique_ptr<scalar> rhoDict;
    if (tools::found(args, "patch"))
    {
        IFstream stream(tools::cloudPropertiesFile(args));
        const dictionary cloudProperties(stream);
        const dictionary& coeffs = tools::adhesiveCoeffs(cloudProperties);
        particleDict.reset(new brachDunn::ElasticMaterial
        (
            tools::particleMaterial(cloudProperties, coeffs)
        ));
        const wallInteractionEntry entry = tools::patchEntry
        (
            coeffs, tools::text(args, "patch"), *particleDict
        );
        if (entry.type() != wallInteractionEntry::interaction::adhesive)
        {
            FatalErrorInFunction
                << "Patch " << tools::text(args, "patch").c_str() << " is of type "
                << entry.typeName() << ", not adhesive: it has no wall"
                << " material" << nl << exit(FatalError);
        }
        wallDict.reset(new brachDunn::ElasticMaterial(entry.model().wallMaterial()));
        const dictionary* constProps = checkedInput::findDictionary
        (
            cloudProperties, "constantProperties", "{ ... }"
        );
        if (constProps && checkedInput::find(*constProps, "rho0"))
        {
            rhoDict.reset
            (
                new scalar(checkedInput::readNumber(*constProps, "rho0"))
            );
        }
    }
    s.particle.E = materialValue(args, "particleE", particleDict ? &particleDict->E : nullptr);
    s.particle.nu = materialValue(args, "particleNu", particleDict ? &particleDict->nu : nullptr);
    s.wall.E = materialValue(args, "wallE", wallDict ? &wallDict->E : nullptr);
    s.wall.nu = materialValue(args, "wallNu", wallDict ? &wallDict->nu : nullptr);
    s.rho = materialValue(args, "rho", rhoDict.get());
    s.minSpeed = tools::number(args, "minSpeed", 10);
    s.restitutionType = tools::wordOption(args, "restitution", "powerLaw");
    s.adhesionType = tools::wordOption(args, "adhesion", "powerLaw");
    s.refine = !tools::found(args, "noRefine");

    brachDunn::ImpactFitResult fit;
    try
    {
        fit = brachDunn::fitImpacts(data, s);
    }
    catch (const brachDunn::InputError& err)
    {
        FatalErrorInFunction
            << "impactFit on " << dataFile.c_str() << ": " << err.what() << nl
            << exit(FatalError);
    }

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
        plot(fileName(tools::text(args, "plot")), data, fit, s);
    }
    return 0;
}
