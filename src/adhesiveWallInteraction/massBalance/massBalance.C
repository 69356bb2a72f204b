// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "massBalance.H"
#include "InputError.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::massBalance::writeTo(const fileName& path, const word& cloudName)
{
    file_ = std::make_shared<OFstream>(path);
    *file_
        << "# adhesiveWallInteraction mass balance of cloud " << cloudName
        << " at write times [kg]" << nl << "# time";
    for (const column& c : columns())
    {
        *file_ << '\t' << c.name;
    }
    *file_ << endl;
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
    const scalar escaped,
    const scalar resuspended
)
{
    injected_ = injected;
    airborne_ = airborne;
    captured_ = captured;
    escaped_ = escaped;
    resuspended_ = resuspended;
    if (!initial_)
    {
        initial_ = airborne + captured - resuspended + escaped - injected;
    }
}


Foam::scalar Foam::massBalance::residual() const
{
    return
        injected_ + initial_.value_or(0)
      - (airborne_ + captured_ - resuspended_ + escaped_);
}


const std::vector<Foam::massBalance::column>& Foam::massBalance::columns()
{
    static const std::vector<column> table
    {
        {"injected", "injected", [](const massBalance& b)
            { return b.injected_; }},
        {"initial", "initial", [](const massBalance& b)
            { return b.initial_.value_or(0); }},
        {"airborne", "airborne", [](const massBalance& b)
            { return b.airborne_; }},
        {"captured", "captured", [](const massBalance& b)
            { return b.captured_; }},
        {"escaped", "escaped", [](const massBalance& b)
            { return b.escaped_; }},
        {"resuspended", "resuspended", [](const massBalance& b)
            { return b.resuspended_; }},
        {
            "residual",
            "injected + initial - (airborne + captured - resuspended"
            " + escaped)",
            [](const massBalance& b) { return b.residual(); }
        },
    };
    return table;
}


void Foam::massBalance::write(Ostream& os, const word& timeName) const
{
    os  << "    adhesiveWallInteraction mass balance [kg]" << nl;
    for (const column& c : columns())
    {
        const std::string label(c.label);
        os  << "      - " << label.c_str()
            << std::string(label.size() < 28 ? 28 - label.size() : 1, ' ').c_str()
            << "= " << c.value(*this) << nl;
    }

    if (file_)
    {
        *file_ << timeName;
        for (const column& c : columns())
        {
            *file_ << '\t' << brachDunn::toText(c.value(*this)).c_str();
        }
        *file_ << endl;
    }
}
