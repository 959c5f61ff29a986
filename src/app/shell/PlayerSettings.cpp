#include "shell/PlayerSettings.hpp"

#include "render/Look.hpp"
#include "shell/AppOptions.hpp"
#include "shell/Notices.hpp"
#include "shell/Trace.hpp"

#include <abalike/save/SaveStore.hpp>

namespace abalike::app
{

PlayerSettings::PlayerSettings(const AppOptions& options, SaveStore* store, Trace& trace, Notices& notices)
    : m_options(options), m_store(store), m_trace(trace), m_notices(notices)
{
    if (m_store != nullptr)
        m_settings = m_store->settings();
    setActiveLook(lookFor(m_settings.palette, m_settings.highContrast));
}

Wording PlayerSettings::wording() const
{
    return m_options.wording.value_or(m_settings.wording);
}

PlayMode PlayerSettings::mode() const
{
    return m_mode.value_or(m_options.mode.value_or(m_settings.mode));
}

bool PlayerSettings::sizeFromCommandLine() const
{
    return m_options.width.has_value();
}

void PlayerSettings::setMode(PlayMode mode)
{
    m_mode = mode;
    if (m_settings.mode != mode)
    {
        Settings settings = m_settings;
        settings.mode = mode;
        update(settings);
    }
}

void PlayerSettings::update(const Settings& settings)
{
    const Settings before = m_settings;
    m_settings = settings;
    setActiveLook(lookFor(settings.palette, settings.highContrast));
    if (m_applied)
        m_applied(before, settings);
    m_trace.write("settings", nlohmann::json::parse(settingsToJson(settings)));
    if (!m_options.scripted() && m_store != nullptr)
        m_store->saveSettings(settings);
    if (m_store != nullptr)
        m_notices.takeMessagesOf(*m_store);
}

} // namespace abalike::app
