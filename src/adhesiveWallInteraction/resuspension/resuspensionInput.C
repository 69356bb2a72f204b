// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "resuspensionInput.H"
#include "wallInteractionEntry.H"


std::optional<Foam::resuspensionSettings> Foam::readResuspension
(
    const dictionary& dict,
    const std::optional<brachDunn::ElasticMaterial>& wall,
    const std::function<brachDunn::ElasticMaterial()>& particle,
    const checkedInput::magnitudes& magnitudes
)
{
    if (!checkedInput::findDictionary(dict, "resuspension", "{ type ...; ... }"))
    {
        return std::nullopt;
    }
    const dictionary sub
    (
        checkedInput::subDictionary
        (
            dict, "resuspension", "{ type ...; ... }", "resuspension"
        )
    );

    // The law, selected by type (resuspensionModel's run-time table)
    const wordList types(resuspensionModel::types());
    const word type(checkedInput::readWord(sub, "type", word::null, types));
    if (type.empty())
    {
        std::string names;
        for (const word& name : types)
        {
            names += (names.empty() ? "" : " or ") + name;
        }
        checkedInput::fail(sub, "type", "missing", "must be " + names);
    }
    resuspensionSettings settings;
    settings.model.reset
    (
        resuspensionModel::New
        (
            type, {sub, wall, particle, magnitudes}, settings.seed,
            settings.defaulted
        ).ptr()
    );
    return settings;
}


// ************************************************************************* //
