// SPDX-License-Identifier: MIT
#include "export_files.h"

#include "charts/motion_track.h"

#include "core/io/atomic_file.h"
#include "core/params.h"

#include <QFileInfo>
#include <QSaveFile>

namespace ab::ui {

void saveImageAtomically(const QImage& image, const QString& path)
{
    if (QFileInfo(path).suffix().toLower() != "png")
        throw InputError(path.toStdString() + ": the 3D view is saved as PNG (use .png)");
    if (image.isNull())
        throw InputError(path.toStdString() + ": there is no image to save");
    checkWritable(path.toStdString());
    QSaveFile file(path); // written beside the target, renamed on commit()
    if (!file.open(QIODevice::WriteOnly))
        throw InputError(path.toStdString() + ": cannot write (" + file.errorString().toStdString() + ")");
    if (!image.save(&file, "PNG"))
        throw InputError(path.toStdString() + ": PNG encoding failed");
    if (!file.commit())
        throw InputError(path.toStdString() + ": write failed (" + file.errorString().toStdString() + ")");
}

void saveMotionCsv(const MotionTrack& track, int axes, int ball, const QString& path)
{
    writeFileAtomically(path.toStdString(), [&](std::ostream& out) { writeMotionCsv(out, track, axes, ball); });
}

} // namespace ab::ui
