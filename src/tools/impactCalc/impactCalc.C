// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    impactCalc

Description
    Try a wall model before a run: the impacts of the adhesiveWallInteraction
    model of a case's cloud properties on one patch, over diameters, speeds
    and angles, as CSV; or the critical (capture) speeds; or, for one
    impact, the Hertz quantities, the force review of Brach & Dunn's
    Eqs. 28-35 and the energy partition, laid out like the paper's Table 1.

Usage
    \b impactCalc -patch NAME [OPTIONS]

    Sweep (one line per diameter, speed and angle):
        diameter,speed,angle,un,ut,R,gamma,WA,captured,unOut,utOut,energyLoss
    SI units, angle in degrees from the wall normal, captured 0 or 1,
    unOut and utOut 0 when captured, WA <= 0 (the columns and their units
    are also in impactCalc -help). A list option takes one value or a list:
    -diameters 5e-6, or -diameters "(2.58e-6 4.9e-6)".

    -critical: diameter,angle,criticalSpeed,criticalNormalSpeed
    (consistent by default, the paper's Eq. 26 with -criticalMethod paper;
    0 when never captured, inf when captured at every speed).

    Options:
      -dict FILE          cloud properties (default: the release's, in constant/:
                          kinematicCloudProperties, or the Foundation's
                          cloudProperties)
      -patch NAME         the patch whose entry applies (matched as the
                          solver matches it, on the case's mesh when it has one)
      -rho VALUE          particle density [kg/m^3] (default constantProperties rho0)
      -diameters "(..)"   [m]
      -speeds "(..)"      total incoming speeds [m/s]
      -angles "(..)"      [deg from the normal] (default (0))
      -critical, -criticalMethod consistent|paper
      -diagnostics        one impact (one diameter, speed and angle) in detail
      -measured VALUE     with -diagnostics: the measured rebound normal speed,
                          giving W_A from Eq. 18 as the paper's Table 1 does
      -lifshitz, -separation, -humidity, -charge, -potential: force review inputs
      -output FILE        write the CSV there
      -precision N        significant digits of the CSV (default 10)
      -plot FILE.png      plot it with gnuplot

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "caseWallModel.H"
#include "diagnostics.H"
#include "impactCalcOptions.H"
#include "gnuplot.H"
#include "mathematicalConstants.H"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace Foam;

namespace
{

//- A list option, each value checked (angles: in [0, 90) degrees;
//  anything else: > 0); the default when absent and one is given
scalarList listOption
(
    const argList& args,
    const word& name,
    const scalarList& deflt
)
{
    if (!tools::found(args, name) && !deflt.empty())
    {
        return deflt;
    }
    const scalarList values(tools::list(args, name));
    const bool angles = (name == "angles");
    for (const scalar v : values)
    {
        if (angles ? !(v >= 0 && v < 90) : !(v > 0))
        {
            FatalErrorInFunction
                << "Option -" << name << ": value " << v
                << (angles ? " must be in [0, 90) degrees" : " must be > 0")
                << nl << exit(FatalError);
        }
    }
    return values;
}


//- The diameters asked for, each checked as a magnitude too (5 typed for
//  5 um stops)
scalarList diameterList
(
    const argList& args,
    const tools::caseWallModel& wallModel
)
{
    const scalarList diameters = listOption(args, "diameters", scalarList());
    for (const scalar d : diameters)
    {
        wallModel.checkMagnitude
        (
            args, "diameters", d, brachDunn::magnitude::diameter
        );
    }
    return diameters;
}


//- The one value a list option may hold (-diagnostics)
scalar single(const argList& args, const word& name, const scalarList& values)
{
    if (values.size() != 1)
    {
        FatalErrorInFunction
            << "Option -" << name << " " << tools::text(args, name).c_str()
            << ": -diagnostics takes one value" << nl << exit(FatalError);
    }
    return values[0];
}


inline scalar radians(const scalar degrees)
{
    return degrees*constant::mathematical::pi/180;
}


//- One row per diameter, angle and speed: the entry's impact as the solver
//  computes it, a particle moving at (ut, 0, -un) onto a floor
void sweep
(
    std::ostream& os,
    const wallInteractionEntry& entry,
    const scalar rho,
    const scalarList& diameters,
    const scalarList& speeds,
    const scalarList& angles,
    std::vector<tools::plotSeries>& series
)
{
    const vector nw(0, 0, -1);
    os  << "diameter,speed,angle,un,ut,R,gamma,WA,captured,unOut,utOut,"
        << "energyLoss\n";
    for (const scalar d : diameters)
    {
        for (const scalar angle : angles)
        {
            // Rebounds joined by lines, captures (rebound ratio 0) as points
            // of their own: no line across the critical speed
            std::ostringstream title;
            title << d << " m, " << angle << " deg";
            tools::plotSeries rebounds{title.str(), "linespoints", {}};
            tools::plotSeries captures{title.str() + ", captured", "points", {}};
            for (const scalar v : speeds)
            {
                const vector U
                (
                    v*std::sin(radians(angle)), 0, -v*std::cos(radians(angle))
                );
                const wallImpact r = tools::coreCall
                (
                    [&]{ return entry.impact(d, rho, U, nw); },
                    {
                        {"d", "diameters"}, {"rho", "rho"}, {"un", "speeds"},
                        {"ut", "speeds"}
                    }
                );
                const bool captured = r.outcome == brachDunn::Fate::capture;
                os  << d << ',' << v << ',' << angle << ',' << r.un << ','
                    << r.ut << ',' << r.R << ',' << r.gamma << ',' << r.WA
                    << ',' << (captured ? 1 : 0) << ',' << r.unOut << ','
                    << r.utOut << ',' << r.energyLoss << '\n';
                (captured ? captures : rebounds).points.push_back
                (
                    {v, captured ? 0 : r.unOut/r.un}
                );
            }
            for (tools::plotSeries* part : {&rebounds, &captures})
            {
                if (!part->points.empty())
                {
                    series.push_back(*part);
                }
            }
        }
    }
}


//- One row per diameter and angle: the critical (capture) speed
void criticalSpeeds
(
    std::ostream& os,
    const brachDunn::ImpactModel& model,
    const scalar rho,
    const scalarList& diameters,
    const scalarList& angles,
    const word& method,
    std::vector<tools::plotSeries>& series
)
{
    os << "diameter,angle,criticalSpeed,criticalNormalSpeed\n";
    for (const scalar angle : angles)
    {
        std::ostringstream title;
        title << angle << " deg";
        series.push_back({title.str(), "linespoints", {}});
    }
    for (const scalar d : diameters)
    {
        forAll(angles, anglei)
        {
            const brachDunn::CriticalSpeed c = tools::coreCall
            (
                [&]
                {
                    return model.criticalSpeed
                    (
                        brachDunn::Particle{d, rho},
                        std::tan(radians(angles[anglei])),
                        method == "paper"
                      ? brachDunn::CriticalMethod::paper
                      : brachDunn::CriticalMethod::consistent
                    );
                },
                {{"d", "diameters"}, {"rho", "rho"}}
            );
            os << d << ',' << angles[anglei] << ',';
            if (c.status == brachDunn::CriticalSpeed::Status::alwaysCaptured)
            {
                os << "inf,inf\n";
            }
            else
            {
                os << c.speed << ',' << c.normalSpeed << '\n';
                series[anglei].points.push_back({d, c.speed});
            }
        }
    }
}

//- The stream the CSV goes to (-output FILE, else standard output), with
//  the precision asked for
std::ostream& output(const argList& args, std::unique_ptr<std::ofstream>& file)
{
    if (tools::found(args, "output"))
    {
        file = std::make_unique<std::ofstream>(tools::fileOption(args, "output"));
        if (!file->good())
        {
            FatalErrorInFunction
                << "Option -output " << tools::text(args, "output").c_str()
                << ": cannot write this file" << nl << exit(FatalError);
        }
    }
    std::ostream& os = file ? *file : std::cout;
    const label precision = tools::integer(args, "precision", 10);
    if (precision < 1 || precision > 17)
    {
        FatalErrorInFunction << "Option -precision " << precision
            << ": must be in [1, 17]" << nl << exit(FatalError);
    }
    os << std::setprecision(precision);
    return os;
}


//- The adhesive entry of the patch (what: what needs it)
const wallInteractionEntry& adhesiveEntry
(
    const wallInteractionEntry& entry,
    const word& patchName,
    const char* what
)
{
    if (entry.type() != wallInteractionEntry::interaction::adhesive)
    {
        FatalErrorInFunction
            << "Patch " << patchName << " is of type " << entry.typeName()
            << ": " << what << " an adhesive entry" << nl
            << exit(FatalError);
    }
    return entry;
}


//- The critical speeds of the entry, by the method asked for
void critical
(
    std::ostream& os,
    const argList& args,
    const tools::caseWallModel& wallModel,
    const word& patchName,
    std::vector<tools::plotSeries>& series
)
{
    const wallInteractionEntry& entry =
        adhesiveEntry(wallModel.entry(), patchName, "critical speeds need");
    const word method(tools::wordOption(args, "criticalMethod", "consistent"));
    if (method != "consistent" && method != "paper")
    {
        FatalErrorInFunction
            << "Option -criticalMethod " << method
            << ": valid methods are consistent and paper" << nl
            << exit(FatalError);
    }
    criticalSpeeds
    (
        os, entry.model(), wallModel.particleDensity(args),
        diameterList(args, wallModel),
        listOption(args, "angles", scalarList(1, Zero)), method, series
    );
}


//- One impact in detail
void diagnose
(
    std::ostream& os,
    const argList& args,
    const tools::caseWallModel& wallModel,
    const word& patchName
)
{
    const scalarList diameters = diameterList(args, wallModel);
    const scalarList speeds = listOption(args, "speeds", scalarList());
    const scalarList angles = listOption(args, "angles", scalarList(1, Zero));
    writeDiagnostics
    (
        os, args, patchName,
        adhesiveEntry(wallModel.entry(), patchName, "-diagnostics needs"),
        single(args, "diameters", diameters), wallModel.particleDensity(args),
        single(args, "speeds", speeds),
        tools::found(args, "angles") ? single(args, "angles", angles) : 0
    );
}


void plotSeries
(
    const argList& args,
    const std::vector<tools::plotSeries>& series,
    const bool critical
)
{
    tools::plot
    (
        tools::fileOption(args, "plot"),
        series,
        critical
      ? "set key outside right\nset grid\nset logscale x\n"
        "set format x '%g'\nset format y '%g'\n"
        "set logscale y\nset xlabel 'particle diameter [m]'\n"
        "set ylabel 'critical speed [m/s]'\n"
      : "set key outside right\nset grid\nset logscale x\n"
        "set format x '%g'\n"
        "set yrange [0:*]\nset xlabel 'incoming speed [m/s]'\n"
        "set ylabel 'rebound ratio Un''/un'\n"
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    addOptions();

    #include "setRootCase.H"

    checkOptionConflicts(args);
    if (tools::found(args, "plot"))
    {
        tools::checkPlotFile(tools::fileOption(args, "plot"));
    }
    const word patchName(tools::text(args, "patch"));
    const tools::caseWallModel wallModel(args, patchName);
    const wallInteractionEntry& entry = wallModel.entry();
    if
    (
        entry.type() == wallInteractionEntry::interaction::escape
     || entry.type() == wallInteractionEntry::interaction::none
    )
    {
        FatalErrorInFunction
            << "Patch " << patchName << " is of type " << entry.typeName()
            << ": there is no impact to compute" << nl << exit(FatalError);
    }

    std::unique_ptr<std::ofstream> file;
    std::ostream& os = output(args, file);
    std::vector<tools::plotSeries> series;
    const bool criticalSpeeds = tools::found(args, "critical");
    if (criticalSpeeds)
    {
        critical(os, args, wallModel, patchName, series);
    }
    else if (tools::found(args, "diagnostics"))
    {
        diagnose(os, args, wallModel, patchName);
    }
    else
    {
        sweep
        (
            os, entry, wallModel.particleDensity(args),
            diameterList(args, wallModel),
            listOption(args, "speeds", scalarList()),
            listOption(args, "angles", scalarList(1, Zero)), series
        );
    }
    os.flush();

    if (tools::found(args, "plot"))
    {
        plotSeries(args, series, criticalSpeeds);
    }
    return 0;
}
