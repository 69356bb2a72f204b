// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "massBalance.H"
#include "InputError.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::massBalance::writeTo(const fileName& path, const word& cloudName)
{
    file_ = std::make_shared<OFstream>(path);
    *file_
        << "# adhesiveWallInteraction mass balance of cloud " << cloudName
        << " at write times [kg]" << nl
        << "# time\tinjected\tinitial\tairborne\tcaptured\tescaped"
        << "\tresidual" << endl;
}


Foam::string Foam::massBalance::storedText() const
{
    return initial_ ? string(brachDunn::toText(*initial_)) : string();
}


void Foam::massBalance::restore(const string& stored)
{
    initial_.reset();
    if (!stored.empty())
    {
        initial_ = std::stod(stored);
    }
}


void Foam::massBalance::update
(
    const scalar injected,
    const scalar airborne,
    const scalar captured,
    const scalar escaped
)
{
    injected_ = injected;
    airborne_ = airborne;
    captured_ = captured;
    escaped_ = escaped;
    if (!initial_)
    {
        initial_ = airborne + captured + escaped - injected;
    }
}


Foam::scalar Foam::massBalance::residual() const
{
    return
        injected_ + initial_.value_or(0) - (airborne_ + captured_ + escaped_);
}


void Foam::massBalance::write(Ostream& os, const word& timeName) const
{
    const scalar initial = initial_.value_or(0);
    os  << "    adhesiveWallInteraction mass balance [kg]" << nl
        << "      - injected                    = " << injected_ << nl
        << "      - initial                     = " << initial << nl
        << "      - airborne                    = " << airborne_ << nl
        << "      - captured                    = " << captured_ << nl
        << "      - escaped                     = " << escaped_ << nl
        << "      - injected + initial - (airborne + captured + escaped) = "
        << residual() << nl;

    if (file_)
    {
        *file_ << timeName;
        for
        (
            const scalar value
          : {injected_, initial, airborne_, captured_, escaped_, residual()}
        )
        {
            *file_ << '\t' << brachDunn::toText(value).c_str();
        }
        *file_ << endl;
    }
}
