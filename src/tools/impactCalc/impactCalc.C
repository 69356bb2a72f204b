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
    unOut and utOut 0 when captured, WA <= 0.

    -critical: diameter,angle,criticalSpeed,criticalNormalSpeed
    (consistent by default, the paper's Eq. 26 with -criticalMethod paper;
    0 when never captured, inf when captured at every speed).

    Options:
      -dict FILE          cloud properties (default constant/kinematicCloudProperties)
      -patch NAME         the patch whose entry applies
      -rho VALUE          particle density [kg/m^3] (default constantProperties rho0)
      -diameters "(..)"   [m]
      -speeds "(..)"      total incoming speeds [m/s]
      -angles "(..)"      [deg from the normal] (default (0))
      -critical, -criticalMethod consistent|paper
      -diagnostics        one impact (first diameter, speed and angle) in detail
      -measured VALUE     with -diagnostics: the measured rebound normal speed,
                          giving W_A from Eq. 18 as the paper's Table 1 does
      -lifshitz, -separation, -humidity, -charge, -potential: force review inputs
      -output FILE        write the CSV there
      -precision N        significant digits of the CSV (default 10)
      -plot FILE.png      plot it with gnuplot

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "cloudPatchModel.H"
#include "gnuplot.H"
#include "ContactForces.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "scalarList.H"
#include "mathematicalConstants.H"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
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


//- Degrees to radians
inline scalar radians(const scalar degrees)
{
    return degrees*constant::mathematical::pi/180;
}


//- Run a core call, turning its input errors into fatal errors
template<class Call>
auto coreCall(const Call& call) -> decltype(call())
{
    try
    {
        return call();
    }
    catch (const brachDunn::InputError& err)
    {
        FatalErrorInFunction << err.what() << nl << exit(FatalError);
        throw;
    }
}


//- One impact of any patch type, in the core's result form
brachDunn::ImpactResult impactOn
(
    const wallInteractionEntry& entry,
    const brachDunn::Particle& particle,
    scalar un,
    scalar ut
)
{
    using interaction = wallInteractionEntry::interaction;
    if (entry.type() == interaction::adhesive)
    {
        return coreCall([&]{ return entry.model().impact(particle, un, ut); });
    }

    brachDunn::ImpactResult r;
    r.un = un;
    r.ut = ut;
    const scalar m = particle.mass();
    const scalar kinetic = 0.5*m*(un*un + ut*ut);
    if (entry.type() == interaction::stick)
    {
        r.outcome = brachDunn::Outcome::captured;
        r.energyLoss = kinetic;
        return r;
    }
    // rebound: standardWallInteraction's U -= (1 + e) Un n; U -= mu Ut
    r.outcome = brachDunn::Outcome::rebound;
    r.R = entry.e();
    r.unOut = entry.e()*un;
    r.utOut = (1 - entry.mu())*ut;
    r.energyLoss =
        kinetic - 0.5*m*(r.unOut*r.unOut + r.utOut*r.utOut);
    return r;
}


//- A curve of a plot
struct Series
{
    std::string title;
    std::vector<std::pair<double, double>> points;
};


//- Draw the series with gnuplot into png (data and script beside it)
void plot
(
    const fileName& png,
    const std::vector<Series>& series,
    const std::string& xlabel,
    const std::string& ylabel,
    bool logY
)
{
    const fileName data = png.lessExt() + ".dat";
    {
        std::ofstream out(data);
        out << std::setprecision(10);
        for (const Series& s : series)
        {
            out << "# " << s.title << '\n';
            for (const auto& [x, y] : s.points)
            {
                out << x << ' ' << y << '\n';
            }
            out << "\n\n";
        }
    }
    std::ostringstream gp;
    gp  << "set key outside right\n"
        << "set grid\n"
        << "set logscale x\n"
        << (logY ? "set logscale y\n" : "set yrange [0:*]\n")
        << "set xlabel '" << xlabel << "'\n"
        << "set ylabel '" << ylabel << "'\n"
        << "plot";
    for (std::size_t i = 0; i < series.size(); ++i)
    {
        gp  << (i ? ", \\\n    " : " ") << "'" << data.c_str() << "' index "
            << i << " using 1:2 with linespoints title '" << series[i].title
            << "'";
    }
    gp << '\n';
    tools::gnuplot(png, gp.str());
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Impacts of an adhesiveWallInteraction patch entry over diameters,"
        " speeds and angles; critical speeds; one impact in detail"
    );
    argList::noParallel();
    compat::noBanner();
    argList::addOption("dict", "file", "cloud properties file");
    argList::addOption("patch", "name", "patch whose entry applies");
    argList::addOption("rho", "value", "particle density [kg/m^3]");
    argList::addOption("diameters", "list", "particle diameters [m]");
    argList::addOption("speeds", "list", "incoming speeds [m/s]");
    argList::addOption("angles", "list", "angles from the normal [deg]");
    argList::addBoolOption("critical", "critical speeds instead");
    argList::addOption
    (
        "criticalMethod", "name", "consistent (default) or paper (Eq. 26)"
    );
    argList::addBoolOption("diagnostics", "one impact in detail");
    argList::addOption("measured", "value", "measured rebound speed [m/s]");
    argList::addOption("lifshitz", "value", "h for the force review [J]");
    argList::addOption("separation", "value", "z for the force review [m]");
    argList::addOption("humidity", "value", "relative humidity [%]");
    argList::addOption("charge", "value", "particle charge [C]");
    argList::addOption("potential", "value", "contact potential [V]");
    argList::addOption("output", "file", "write the CSV to this file");
    argList::addOption("precision", "digits", "significant digits (10)");
    argList::addOption("plot", "file.png", "plot with gnuplot");

    #include "setRootCase.H"


    const fileName propsFile = tools::cloudPropertiesFile(args);
    IFstream propsStream(propsFile);
    const dictionary cloudProperties(propsStream);
    const dictionary& coeffs = tools::adhesiveCoeffs(cloudProperties);
    const brachDunn::ElasticMaterial particleMaterial =
        tools::particleMaterial(cloudProperties, coeffs);
    const word patchName(tools::text(args, "patch"));
    const wallInteractionEntry entry =
        tools::patchEntry(coeffs, patchName, particleMaterial);
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
    const scalar rho = tools::particleDensity(args, cloudProperties);

    const scalarList diameters =
        listOption(args, "diameters", scalarList());
    const scalarList angles =
        listOption(args, "angles", scalarList(1, Zero));
    const bool critical = tools::found(args, "critical");

    std::unique_ptr<std::ofstream> file;
    if (tools::found(args, "output"))
    {
        file.reset(new std::ofstream(tools::text(args, "output")));
        if (!file->good())
        {
            FatalErrorInFunction << "Cannot write " << tools::text(args, "output").c_str() << nl
                << exit(FatalError);
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
    std::vector<Series> series;

    if (critical)
    {
        if (entry.type() != wallInteractionEntry::interaction::adhesive)
        {
            FatalErrorInFunction
                << "Patch " << patchName << " is of type "
                << entry.typeName() << ": critical speeds need an adhesive"
                << " entry" << nl << exit(FatalError);
        }
        const word method(tools::wordOption(args, "criticalMethod", "consistent"));
        if (method != "consistent" && method != "paper")
        {
            FatalErrorInFunction
                << "Option -criticalMethod " << method
                << ": valid methods are consistent and paper" << nl
                << exit(FatalError);
        }
        os << "diameter,angle,criticalSpeed,criticalNormalSpeed\n";
        for (const scalar angle : angles)
        {
            std::ostringstream title;
            title << angle << " deg";
            series.push_back({title.str(), {}});
        }
        for (const scalar d : diameters)
        {
            forAll(angles, anglei)
            {
                const scalar angle = angles[anglei];
                const brachDunn::CriticalSpeed c = coreCall([&]
                {
                    return entry.model().criticalSpeed
                    (
                        brachDunn::Particle{d, rho},
                        std::tan(radians(angle)),
                        method == "paper"
                      ? brachDunn::CriticalMethod::paper
                      : brachDunn::CriticalMethod::consistent
                    );
                });
                os << d << ',' << angle << ',';
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
    else
    {
        const scalarList speeds =
            listOption(args, "speeds", scalarList());

        if (tools::found(args, "diagnostics"))
        {
            #include "diagnostics.H"
        }
        else
        {
            os  << "diameter,speed,angle,un,ut,R,gamma,WA,captured,"
                << "unOut,utOut,energyLoss\n";
            for (const scalar d : diameters)
            {
                for (const scalar angle : angles)
                {
                    std::ostringstream title;
                    title << d << " m, " << angle << " deg";
                    series.push_back({title.str(), {}});
                    for (const scalar v : speeds)
                    {
                        const scalar un = v*std::cos(radians(angle));
                        const scalar ut = v*std::sin(radians(angle));
                        const brachDunn::ImpactResult r =
                            impactOn(entry, brachDunn::Particle{d, rho}, un, ut);
                        os  << d << ',' << v << ',' << angle << ','
                            << un << ',' << ut << ',' << r.R << ','
                            << r.gamma << ',' << r.WA << ','
                            << (r.captured() ? 1 : 0) << ','
                            << r.unOut << ',' << r.utOut << ','
                            << r.energyLoss << '\n';
                        series.back().points.push_back
                        (
                            {v, r.captured() ? 0 : r.unOut/un}
                        );
                    }
                }
            }
        }
    }
    os.flush();

    if (tools::found(args, "plot"))
    {
        if (critical)
        {
            plot
            (
                fileName(tools::text(args, "plot")), series, "particle diameter [m]",
                "critical speed [m/s]", true
            );
        }
        else
        {
            plot
            (
                fileName(tools::text(args, "plot")), series, "incoming speed [m/s]",
                "rebound ratio Un''/un", false
            );
        }
    }

    return 0;
}
