// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "diagnostics.H"
#include "toolOptions.H"
#include "ContactForces.H"
#include "mathematicalConstants.H"

#include <iomanip>

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
    if (entry.type() != wallInteractionEntry::interaction::adhesive)
    {
        FatalErrorInFunction
            << "Patch " << patchName << " is of type " << entry.typeName()
            << ": -diagnostics needs an adhesive entry" << nl
            << exit(FatalError);
    }
    const brachDunn::ImpactModel& model = entry.model();
    const brachDunn::Particle particle{d, rho};
    const scalar radians = angle*constant::mathematical::pi/180;
    const scalar un = v*std::cos(radians);
    const scalar ut = v*std::sin(radians);

    const std::vector<std::pair<std::string, std::string>> optionOf
    {
        {"d", "diameters"}, {"rho", "rho"}, {"un", "speeds"}, {"ut", "speeds"}
    };
    const brachDunn::ImpactResult r =
        tools::coreCall([&]{ return model.impact(particle, un, ut); }, optionOf);
    const brachDunn::HertzContact h =
        tools::coreCall([&]{ return model.hertz(particle, un); }, optionOf);

    // W_A from the model, or from a measured rebound (Eq. 18)
    scalar WA = r.WA, gamma = r.gamma, unOut = r.unOut, utOut = r.utOut;
    const bool measured = tools::found(args, "measured");
    if (measured)
    {
        if (angle != 0)
        {
            FatalErrorInFunction
                << "-measured applies to normal impacts: give -angles \"(0)\""
                << nl << exit(FatalError);
        }
        unOut = tools::number(args, "measured");
        utOut = 0;
        if (!(unOut >= 0 && unOut <= un))
        {
            FatalErrorInFunction
                << "Option -measured " << unOut << ": a rebound speed must be"
                << " >= 0 and no faster than its impact, " << un << " m/s"
                << nl << exit(FatalError);
        }
        const brachDunn::AdhesionLaw::Work w = tools::coreCall
        (
            [&]{ return model.measuredAdhesion(particle, un, unOut); },
            {{"unOut", "measured"}}
        );
        WA = w.WA;
        gamma = w.gamma;
    }

    brachDunn::ForceReviewInputs in;
    in.h = tools::number(args, "lifshitz", in.h);
    in.z = tools::number(args, "separation", in.z);
    in.relativeHumidity = tools::number(args, "humidity", in.relativeHumidity);
    if (tools::found(args, "charge"))
    {
        in.charge = tools::number(args, "charge");
    }
    in.contactPotential = tools::number(args, "potential", in.contactPotential);
    const brachDunn::ContactForces f = tools::coreCall
    (
        [&]{ return brachDunn::contactForces(particle, h.contactRadius, in); },
        {
            {"h", "lifshitz"}, {"z", "separation"},
            {"relativeHumidity", "humidity"}, {"charge", "charge"},
            {"contactPotential", "potential"}
        }
    );

    const scalar m = h.mass;
    const scalar Ti = 0.5*m*(un*un + ut*ut);
    const scalar Tf = 0.5*m*(unOut*unOut + utOut*utOut);
    const scalar deformation = (1 - r.R*r.R)*0.5*m*un*un;
    const scalar friction = 0.5*m*(ut*ut - utOut*utOut);

    const auto line = [&](const char* name, scalar value, const char* unit)
    {
        os << "  " << std::left << std::setw(40) << name << std::setw(14)
           << value << unit << '\n';
    };
    const auto share = [&](const char* name, scalar value)
    {
        os << "  " << std::left << std::setw(40) << name << std::setw(14)
           << value << "J (" << std::setprecision(3) << 100*value/Ti
           << "% T_i)\n" << std::setprecision(4);
    };

    os << std::setprecision(4);
    os  << "Impact on patch " << patchName << " (entry " << entry.name()
        << "), laid out like Table 1 of Brach & Dunn (1992)\n\n"
        << "Particle\n";
    line("d, diameter", particle.d, "m");
    line("rho, density", rho, "kg/m^3");
    line("E, Young's modulus", model.particleMaterial().E, "Pa");
    line("nu, Poisson's ratio", model.particleMaterial().nu, "");
    line("m, mass", m, "kg");
    os << "Wall\n";
    line("E, Young's modulus", model.wallMaterial().E, "Pa");
    line("nu, Poisson's ratio", model.wallMaterial().nu, "");
    os << "Impact mechanics\n";
    line("v, incoming speed", v, "m/s");
    line("angle from the normal", angle, "deg");
    line("v_n, initial normal velocity", un, "m/s");
    line
    (
        measured ? "V_n, final normal velocity (measured)"
                 : "V_n, final normal velocity",
        unOut, "m/s"
    );
    line("V_n/v_n, velocity ratio", unOut/un, "");
    line("V_t, final tangential velocity", utOut, "m/s");
    line("alpha_m, elastic displacement", h.approach, "m");
    line("a_m, contact radius", h.contactRadius, "m");
    line("Hertzian contact force (max)", h.maxForce, "N");
    line
    (
        "F_A, adhesive force (max)",
        brachDunn::adhesionFractureForce(WA, particle.radius(), h.contactRadius),
        "N"
    );
    line("tau, contact duration", h.duration, "s");
    line("R, coefficient of restitution", r.R, "");
    line
    (
        measured ? "gamma, surface energy (from Eq. 18)" : "gamma, surface energy",
        gamma, "J/m^2"
    );
    if (WA > 0)
    {
        os  << "  (the measured rebound is faster than R v_n: by Eq. 18"
            << " adhesion would have given energy, gamma < 0)\n";
    }
    line("T_i, initial kinetic energy", Ti, "J");
    share("T_f, final kinetic energy", Tf);
    share("(1-R^2) m v_n^2/2, deformation energy", deformation);
    share("W_A, work of adhesion fracture (|W_A|)", -WA);
    share("friction loss", friction);
    share("E_h, van der Waals energy (Eq. 34)", f.vanDerWaalsEnergy);
    os << (r.captured() && !measured ? "  captured\n" : "");
    os << "Forces near contact (Eqs. 28-33)\n";
    line("F_vdW, van der Waals", f.vanDerWaals, "N");
    line("F_cap, capillary", f.capillary, "N");
    line("F_g, gravity", f.gravity, "N");
    line("F_i, image", f.image, "N");
    line("F_cp, contact potential", f.contactPotential, "N");
    line("F_sum", f.total, "N");
    line("q, charge", f.charge, "C");
    line("h, Lifshitz - van der Waals constant", in.h, "J");
    line("z, separation", in.z, "m");
}
