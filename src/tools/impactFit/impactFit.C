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

using namespace Foam;

namespace
{

//- An option of the tool: its name, its argument (none: a switch) and use
struct optionEntry
{
    const char* name;
    const char* argument;
    const char* use;
};

const optionEntry fitOptions[] =
{
    {"data", "file", "CSV of diameter,speedIn,speedOut"},
    {"particleE", "value", "particle Young's modulus [Pa]"},
    {"particleNu", "value", "particle Poisson's ratio"},
    {"wallE", "value", "wall Young's modulus [Pa]"},
    {"wallNu", "value", "wall Poisson's ratio"},
    {"minSpeed", "value", "fast/slow split [m/s] (default: from the data)"},
    {"restitution", "type", "powerLaw (default) or constant"},
    {"adhesion", "type", "powerLaw (default) or constant"},
    {"noRefine", nullptr, "the paper's single pass"},
    {"extremeValues", nullptr, "take values that look like unit mistakes as given"},
    {"plot", "file.png", "plot data and fits"}
};


void addOptions()
{
    argList::addNote
    (
        "Fit the restitution and adhesion laws of the Brach & Dunn model to"
        " measured normal impacts. Without -minSpeed, the split between the"
        " fast impacts (restitution) and the slow rebounds (adhesion) is"
        " chosen from the data and the output says which and why. Each"
        " coefficient is printed as value +- standard error with its 95 %"
        " interval (Student's t); the correlation coefficients say what they"
        " are computed over."
    );
    tools::addCaseOptions("patch entry giving the materials");
    for (const optionEntry& o : fitOptions)
    {
        if (o.argument) argList::addOption(o.name, o.argument, o.use);
        else argList::addBoolOption(o.name, o.use);
    }
}


//- The first three comma-separated fields of a line, each a finite number
//  and only that; false when they are not
bool parseImpact(const std::string& text, std::vector<std::string>& fields, scalar values[3])
{
    fields.clear();
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
    bool good = fields.size() == 3;
    for (std::size_t i = 0; good && i < 3; ++i)
    {
        good = tools::parseNumber(fields[i], values[i]);
    }
    return good;
}


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
    std::vector<std::string> fields;
    int line = 0;
    bool first = true;
    // The header's fields: a row with more is one with a decimal comma
    // (1,2 for 1.2) more likely than one with a column the header lacks
    std::size_t headerFields = 0;
    const auto countFields = [](const std::string& t)
    {
        return std::size_t(std::count(t.begin(), t.end(), ',')) + 1;
    };
    while (std::getline(in, text))
    {
        ++line;
        text = text.substr(0, text.find('#'));
        if (text.find_first_not_of(" \t\r,") == std::string::npos) continue;
        scalar values[3] = {0, 0, 0}, number = 0;
        if (!parseImpact(text, fields, values))
        {
            // A header: a first line whose first field is not a number
            if (first && !tools::parseNumber(fields[0], number))
            {
                first = false;
                headerFields = countFields(text);
                continue;
            }
            FatalErrorInFunction
                << file.c_str() << " line " << line << ": expected"
                << " diameter,speedIn,speedOut, each a finite number, found '"
                << text.c_str() << "'" << nl << exit(FatalError);
        }
        if (headerFields >= 3 && countFields(text) > headerFields)
        {
            FatalErrorInFunction
                << file.c_str() << " line " << line << ": "
                << countFields(text) << " fields where the header names "
                << headerFields << ", in '" << text.c_str() << "': a decimal"
                << " comma (write 1.2, not 1,2)?" << nl << exit(FatalError);
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


//- A diameter of the data that can only be a unit mistake (5 typed for
//  5 um) stops, naming the file's line, unless -extremeValues
void checkDiameters
(
    const argList& args,
    const fileName& file,
    const std::vector<brachDunn::Measurement>& data
)
{
    for (const brachDunn::Measurement& m : data)
    {
        const std::string mistake = brachDunn::unitMistake
        (
            brachDunn::magnitude::diameter, "diameter", m.d
        );
        if (!mistake.empty() && !tools::found(args, "extremeValues"))
        {
            FatalErrorInFunction
                << file.c_str() << " line " << m.line << ": "
                << mistake.c_str() << " (-extremeValues takes it as given)"
                << nl << exit(FatalError);
        }
    }
}


//- The materials of the case's adhesive entry of -patch, when given
struct caseMaterials
{
    std::optional<brachDunn::ElasticMaterial> particle, wall;
    std::optional<scalar> rho;

    explicit caseMaterials(const argList& args)
    {
        if (!tools::found(args, "patch")) return;
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
};


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


//- The fit's settings from the options (and the case's materials)
brachDunn::ImpactFitSettings fitSettings(const argList& args)
{
    const caseMaterials materials(args);
    const auto part = [](const auto& material, scalar brachDunn::ElasticMaterial::*member)
    {
        return material ? std::optional<scalar>((*material).*member) : std::nullopt;
    };
    brachDunn::ImpactFitSettings s;
    s.particle.E = materialValue(args, "particleE", part(materials.particle, &brachDunn::ElasticMaterial::E));
    s.particle.nu = materialValue(args, "particleNu", part(materials.particle, &brachDunn::ElasticMaterial::nu));
    s.wall.E = materialValue(args, "wallE", part(materials.wall, &brachDunn::ElasticMaterial::E));
    s.wall.nu = materialValue(args, "wallNu", part(materials.wall, &brachDunn::ElasticMaterial::nu));
    s.rho = materialValue(args, "rho", materials.rho);
    if (tools::found(args, "minSpeed"))
    {
        s.minSpeed = tools::number(args, "minSpeed");
    }
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
    // Magnitudes that can only be unit mistakes (the case's own values
    // were checked when it was read, and -rho with it)
    const bool extreme = tools::found(args, "extremeValues");
    for (const auto& [option, value, magnitude] :
        {
            std::tuple{"particleE", s.particle.E, &brachDunn::magnitude::youngsModulus},
            std::tuple{"wallE", s.wall.E, &brachDunn::magnitude::youngsModulus},
            std::tuple{"rho", s.rho, &brachDunn::magnitude::density}
        })
    {
        const bool checkedWithCase = materials.rho && option == word("rho");
        if (tools::found(args, option) && !checkedWithCase)
        {
            tools::checkMagnitude
            (
                args, option, value, *magnitude, extreme, "-extremeValues"
            );
        }
    }
    return s;
}


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


//- The law's form, by family and type
std::string lawForm(const std::string& family, const std::string& type)
{
    const std::pair<const char*, const char*> forms[] =
    {
        {"Restitution powerLaw", "R = k/(k + un^p), un in m/s"},
        {"Restitution constant", "R the same at every speed"},
        {"Adhesion powerLaw", "gamma = c un^n, gamma in J/m^2, un in m/s"},
        {"Adhesion constant", "gamma [J/m^2] the same at every speed"}
    };
    for (const auto& [name, form] : forms)
    {
        if (family + " " + type == name) return std::string(", ") + form;
    }
    return "";
}


//- A law's coefficients (value +- standard error, 95 % interval) and its
//  correlation coefficient: what it compares, over which rebounds
void printLaw
(
    std::ostream& os,
    const char* family,
    const brachDunn::LawFit& law,
    const std::string& compared,
    const std::string& over
)
{
    os  << family << ' ' << law.type << lawForm(family, law.type) << ":\n";
    for (std::size_t i = 0; i < law.values.size(); ++i)
    {
        const char* unit =
            law.names[i] == "c" || law.names[i] == "gamma" ? " J/m^2" : "";
        std::ostringstream figure;
        figure
            << std::left << std::setw(6) << law.names[i]
            << std::setprecision(5) << law.values[i] << " +- "
            << std::setprecision(2) << law.standardErrors[i] << unit;
        os  << "    " << std::left << std::setw(32) << figure.str()
            << std::setprecision(4) << "95 % interval " << law.lower[i]
            << " to " << law.upper[i] << unit << '\n';
        // A surface energy beyond any solid's: speeds in another unit?
        const std::string outside =
            law.names[i] == "c" || law.names[i] == "gamma"
          ? brachDunn::outsideRange
            (
                brachDunn::magnitude::surfaceEnergy, law.names[i],
                law.values[i]
            )
          : std::string();
        if (!outside.empty() && !law.atBound[i])
        {
            os  << "    warning: " << outside << " (are the speeds in m/s?)\n";
        }
        if (law.atBound[i])
        {
            os  << "    warning: " << law.names[i] << " ended at an end of its"
                << " range: the best fit lies there or beyond, so this is the"
                << " bound's value, not the data's, and its interval means"
                << " little";
            if (law.values.size() > 1)
            {
                os  << "; a law of one coefficient ("
                    << (std::string(family) == "Restitution"
                        ? "-restitution" : "-adhesion")
                    << " constant) may be all the data can tell";
            }
            os  << '\n';
        }
    }
    if (law.correlation)
    {
        os  << "    correlation coefficient " << std::setprecision(4)
            << *law.correlation << ": Pearson's r of " << compared << ", over "
            << over << '\n';
    }
    else
    {
        os  << "    correlation coefficient: none, the law is constant (one"
            << " value fitted to every point), so there is no correlation to"
            << " report over " << over << '\n';
    }
}


//- What the figures are
void printExplanation
(
    std::ostream& os,
    const brachDunn::ImpactFitResult& fit,
    const brachDunn::ImpactFitSettings& s
)
{
    const brachDunn::LawFit& r = fit.restitution;
    const brachDunn::LawFit& a = fit.adhesion;
    const auto tText = [](const brachDunn::LawFit& law)
    {
        std::ostringstream os;
        os  << law.degreesOfFreedom << " degrees of freedom, Student's t(0.975, "
            << law.degreesOfFreedom << ") = " << std::setprecision(4) << law.t;
        return os.str();
    };
    os  << "\nThe figures: value +- standard error, the square root of the"
        << " coefficient's variance in s^2 (J^T J)^-1 of the least-squares fit,"
        << " s^2 = (sum of squared residuals)/(points - coefficients);\n";
    if (s.refine)
    {
        os  << "  the fit is the joint one of both laws to the rebound ratio"
            << " Un'/un of all " << fit.rebounds << " rebounds, in relative"
            << " residuals (fitted/measured - 1), " << fit.rebounds << " - "
            << r.values.size() + a.values.size() << " coefficients = "
            << tText(r) << "; the rebound speeds scatter about it by s = "
            << std::setprecision(2) << 100**fit.scatter << " %;\n"
            << "  it was started from " << fit.starts
            << " points (three alternating passes, restitution first and"
            << " adhesion first, at each of " << fit.starts/2 << " splits)"
            << " and the one of least residual kept;\n";
    }
    else
    {
        os  << "  single pass: restitution from the rebound ratio of the "
            << r.points << " faster rebounds taken as free of adhesion, "
            << tText(r) << "; adhesion from gamma of the " << a.points
            << " slower ones, " << tText(a) << ";\n";
    }
    std::string logarithmic;
    for (const brachDunn::LawFit* law : {&r, &a})
    {
        for (std::size_t i = 0; i < law->names.size(); ++i)
        {
            if (!law->logarithmic[i]) continue;
            logarithmic += (logarithmic.empty() ? "" : " and ") + law->names[i];
        }
    }
    os  << "  95 % interval: value -+ t x standard error";
    if (!logarithmic.empty())
    {
        os  << " (for " << logarithmic << ", fitted through the logarithm to"
            << " stay positive: value x/ exp(t se/value))";
    }
    os  << ", within the coefficient's range.\n";
}


void printFit
(
    std::ostream& os,
    const fileName& dataFile,
    const std::vector<brachDunn::Measurement>& data,
    const brachDunn::ImpactFitResult& fit,
    const brachDunn::ImpactFitSettings& s
)
{
    std::ostringstream split;
    split << std::setprecision(4) << fit.split.minSpeed << " m/s";
    os  << "impactFit: " << data.size() << " impacts from " << dataFile.c_str()
        << ": " << fit.rebounds << " rebounds fitted, " << fit.captured
        << " captured (left out of the fits)\n"
        << "particle E " << s.particle.E << " Pa, nu " << s.particle.nu
        << ", rho " << s.rho << " kg/m^3; wall E " << s.wall.E << " Pa, nu "
        << s.wall.nu << "\n"
        << "Split: " << fit.split.reason << "\n\n";
    printLaw
    (
        os, "Restitution", fit.restitution,
        "measured and fitted rebound ratio Un'/un",
        "the " + std::to_string(fit.restitution.points)
      + " rebounds faster than " + split.str()
    );
    printLaw
    (
        os, "Adhesion", fit.adhesion,
        "gamma from each rebound (Eqs. 18 and 22) and from the law",
        "the " + std::to_string(fit.adhesion.points)
      + " rebounds at or below " + split.str()
    );
    printExplanation(os, fit, s);
    os  << "\nFor the patch entry of adhesiveWallInteractionCoeffs:\n"
        << "    restitution " << fit.restitution.dictionary() << '\n'
        << "    adhesion    " << fit.adhesion.dictionary() << '\n';
}


//- The fitted rebound ratio of a diameter at log-spaced speeds over
//  [from, to], ending exactly there
tools::plotSeries fittedCurve
(
    const brachDunn::ImpactModel& model,
    double d,
    double rho,
    double from,
    double to,
    const std::string& title,
    const std::string& style
)
{
    tools::plotSeries curve{title, style, {}};
    const int n = std::max(2, int(60*std::log10(to/from)));
    for (int j = 0; j <= n; ++j)
    {
        const double v = j == n ? to : from*std::pow(to/from, double(j)/n);
        const auto r = model.impact(brachDunn::Particle{d, rho}, v, 0);
        curve.points.push_back({v, r.captured() ? 0 : r.unOut/v});
    }
    return curve;
}


//- The data and the fitted curves, by diameter: solid over the measured
//  speeds, dashed where they extrapolate; the split marked
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
    double low = HUGE_VAL, high = 0;
    for (const auto& m : data)
    {
        low = std::min(low, m.speedIn);
        high = std::max(high, m.speedIn);
        if (std::find(diameters.begin(), diameters.end(), m.d) == diameters.end())
        {
            diameters.push_back(m.d);
        }
    }
    const double from = std::min(0.1, low/2), to = std::max(200.0, 2*high);
    std::vector<tools::plotSeries> series;
    for (std::size_t i = 0; i < diameters.size(); ++i)
    {
        const double d = diameters[i];
        std::ostringstream name, colour;
        name << d << " m, ";
        colour << " lc " << i + 1;
        series.push_back({name.str() + "measured", "points pt 7" + colour.str(), {}});
        for (const auto& m : data)
        {
            if (m.d == d) series.back().points.push_back({m.speedIn, m.speedOut/m.speedIn});
        }
        const std::string dashed = "lines dt 2" + colour.str();
        series.push_back(fittedCurve(model, d, s.rho, from, low, "", dashed));
        series.push_back(fittedCurve(model, d, s.rho, low, high, name.str() + "fitted", "lines" + colour.str()));
        series.push_back(fittedCurve(model, d, s.rho, high, to, name.str() + "extrapolated", dashed));
    }
    std::ostringstream settings;
    settings
        << "set logscale x\nset grid\nset key outside right\n"
        << "set yrange [0:1.05]\nset xrange [" << from << ":" << to << "]\n"
        << "set title 'fitted curves dashed where extrapolated, beyond the"
        << " measured " << low << " to " << high << " m/s' font ',10'"
        << " offset 0, 1\n"
        << "set xlabel 'incoming normal speed [m/s]'\n"
        << "set ylabel 'rebound ratio Un''/un'\n"
        << "set arrow from " << fit.split.minSpeed << ", graph 0 to "
        << fit.split.minSpeed << ", graph 1 nohead dashtype 3 lc 'grey40'\n"
        << "set label 'minSpeed " << fit.split.minSpeed << " m/s (fast/slow"
        << " split)' at " << fit.split.minSpeed << ", graph 1 center offset"
        << " 0, 0.7 font ',9' textcolor 'grey40'\n";
    tools::plot(png, series, settings.str());
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
