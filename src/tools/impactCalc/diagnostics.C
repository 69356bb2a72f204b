// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "diagnostics.H"
#include "toolOptions.H"
#include "ContactForces.H"
#include "mathematicalConstants.H"

#include <iomanip>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- What the table shows of one impact
struct impactDetails
{
    brachDunn::ImpactResult r;
    brachDunn::HertzContact h;
    scalar un, ut;
    scalar WA, gamma, unOut, utOut;     //!< the model's, or from -measured
    bool measured;
    brachDunn::ForceReviewInputs in;
    brachDunn::ContactForces f;
};


//- W_A, gamma and the rebound from the measured rebound speed (Eq. 18)
void measuredRebound
(
    const argList& args,
    const brachDunn::ImpactModel& model,
    const brachDunn::Particle& particle,
    const scalar angle,
    impactDetails& x
)
{
    if (angle != 0)
    {
        FatalErrorInFunction
            << "-measured applies to normal impacts: give -angles \"(0)\""
            << nl << exit(FatalError);
    }
    x.unOut = tools::number(args, "measured");
    x.utOut = 0;
    if (!(x.unOut >= 0 && x.unOut <= x.un))
    {
        FatalErrorInFunction
            << "Option -measured " << x.unOut << ": a rebound speed must be"
            << " >= 0 and no faster than its impact, " << x.un << " m/s"
            << nl << exit(FatalError);
    }
    const brachDunn::AdhesionLaw::Work w = tools::coreCall
    (
        [&]{ return model.measuredAdhesion(particle, x.un, x.unOut); },
        {{"unOut", "measured"}}
    );
    x.WA = w.WA;
    x.gamma = w.gamma;
}


//- The forces near contact (Eqs. 28-35) from the options
void forceReview
(
    const argList& args,
    const brachDunn::Particle& particle,
    impactDetails& x
)
{
    x.in.h = tools::number(args, "lifshitz", x.in.h);
    x.in.z = tools::number(args, "separation", x.in.z);
    x.in.relativeHumidity =
        tools::number(args, "humidity", x.in.relativeHumidity);
    if (tools::found(args, "charge"))
    {
        x.in.charge = tools::number(args, "charge");
    }
    x.in.contactPotential =
        tools::number(args, "potential", x.in.contactPotential);
    x.f = tools::coreCall
    (
        [&]
        {
            return brachDunn::contactForces
            (
                particle, x.h.contactRadius, x.in
            );
        },
        {
            {"h", "lifshitz"}, {"z", "separation"},
            {"relativeHumidity", "humidity"}, {"charge", "charge"},
            {"contactPotential", "potential"}
        }
    );
}


//- Table rows: a quantity, and a share of the initial kinetic energy
struct tableWriter
{
    std::ostream& os;
    scalar Ti;

    void line(const char* name, scalar value, const char* unit) const
    {
        os << "  " << std::left << std::setw(40) << name << std::setw(14)
           << value << unit << '\n';
    }

    void share(const char* name, scalar value) const
    {
        os << "  " << std::left << std::setw(40) << name << std::setw(14)
           << value << "J (" << std::setprecision(3) << 100*value/Ti
           << "% T_i)\n" << std::setprecision(4);
    }
};


void writeMechanics
(
    const tableWriter& w,
    const brachDunn::Particle& particle,
    const scalar v,
    const scalar angle,
    const impactDetails& x
)
{
    w.os << "Impact mechanics\n";
    w.line("v, incoming speed", v, "m/s");
    w.line("angle from the normal", angle, "deg");
    w.line("v_n, initial normal velocity", x.un, "m/s");
    w.line
    (
        x.measured ? "V_n, final normal velocity (measured)"
                   : "V_n, final normal velocity",
        x.unOut, "m/s"
    );
    w.line("V_n/v_n, velocity ratio", x.unOut/x.un, "");
    w.line("V_t, final tangential velocity", x.utOut, "m/s");
    w.line("alpha_m, elastic displacement", x.h.approach, "m");
    w.line("a_m, contact radius", x.h.contactRadius, "m");
    w.line("Hertzian contact force (max)", x.h.maxForce, "N");
    w.line
    (
        "F_A, adhesive force (max)",
        brachDunn::adhesionFractureForce
        (
            x.WA, particle.radius(), x.h.contactRadius
        ),
        "N"
    );
    w.line("tau, contact duration", x.h.duration, "s");
    w.line("R, coefficient of restitution", x.r.R, "");
    w.line
    (
        x.measured ? "gamma, surface energy (from Eq. 18)"
                   : "gamma, surface energy",
        x.gamma, "J/m^2"
    );
    if (x.WA > 0)
    {
        w.os<< "  (the measured rebound is faster than R v_n: by Eq. 18"
            << " adhesion would have given energy, gamma < 0)\n";
    }
}


void writeEnergiesAndForces(const tableWriter& w, const impactDetails& x)
{
    const scalar m = x.h.mass;
    w.line("T_i, initial kinetic energy", w.Ti, "J");
    w.share("T_f, final kinetic energy", 0.5*m*(x.unOut*x.unOut + x.utOut*x.utOut));
    w.share("(1-R^2) m v_n^2/2, deformation energy", (1 - x.r.R*x.r.R)*0.5*m*x.un*x.un);
    w.share("W_A, work of adhesion fracture (|W_A|)", -x.WA);
    w.share("friction loss", 0.5*m*(x.ut*x.ut - x.utOut*x.utOut));
    w.share("E_h, van der Waals energy (Eq. 34)", x.f.vanDerWaalsEnergy);
    w.os << (x.r.captured() && !x.measured ? "  captured\n" : "");
    w.os << "Forces near contact (Eqs. 28-33)\n";
    w.line("F_vdW, van der Waals", x.f.vanDerWaals, "N");
    w.line("F_cap, capillary", x.f.capillary, "N");
    w.line("F_g, gravity", x.f.gravity, "N");
    w.line("F_i, image", x.f.image, "N");
    w.line("F_cp, contact potential", x.f.contactPotential, "N");
    w.line("F_sum", x.f.total, "N");
    w.line("q, charge", x.f.charge, "C");
    w.line("h, Lifshitz - van der Waals constant", x.in.h, "J");
    w.line("z, separation", x.in.z, "m");
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::writeDiagnostics
(
    std::ostream& os,
    const argList& args,
    const word& patchName,
    const wallInteractionEntry& entry,
    const scalar d,
    const scalar rho,
    const scalar v,
    const scalar angle
)
{
    const brachDunn::ImpactModel& model = entry.model();
    const brachDunn::Particle particle{d, rho};
    const scalar radians = angle*constant::mathematical::pi/180;

    impactDetails x;
    x.un = v*std::cos(radians);
    x.ut = v*std::sin(radians);
    const std::vector<std::pair<std::string, std::string>> optionOf
    {
        {"d", "diameters"}, {"rho", "rho"}, {"un", "speeds"}, {"ut", "speeds"}
    };
    x.r = tools::coreCall
    (
        [&]{ return model.impact(particle, x.un, x.ut); }, optionOf
    );
    x.h = tools::coreCall([&]{ return model.hertz(particle, x.un); }, optionOf);
    x.WA = x.r.WA;
    x.gamma = x.r.gamma;
    x.unOut = x.r.unOut;
    x.utOut = x.r.utOut;
    x.measured = tools::found(args, "measured");
    if (x.measured)
    {
        measuredRebound(args, model, particle, angle, x);
    }
    forceReview(args, particle, x);

    const tableWriter w{os, 0.5*x.h.mass*(x.un*x.un + x.ut*x.ut)};
    os << std::setprecision(4);
    os  << "Impact on patch " << patchName << " (entry " << entry.name()
        << "), laid out like Table 1 of Brach & Dunn (1992)\n\n"
        << "Particle\n";
    w.line("d, diameter", particle.d, "m");
    w.line("rho, density", rho, "kg/m^3");
    w.line("E, Young's modulus", model.particleMaterial().E, "Pa");
    w.line("nu, Poisson's ratio", model.particleMaterial().nu, "");
    w.line("m, mass", x.h.mass, "kg");
    os << "Wall\n";
    w.line("E, Young's modulus", model.wallMaterial().E, "Pa");
    w.line("nu, Poisson's ratio", model.wallMaterial().nu, "");
    writeMechanics(w, particle, v, angle, x);
    writeEnergiesAndForces(w, x);
}
