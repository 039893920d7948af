// SPDX-License-Identifier: MIT
#include "export_files.h"

#include "charts/chart_data_csv.h"

#include "core/io/atomic_file.h"
#include "core/params.h"

#include <QBuffer>
#include <QFileInfo>

#include <streambuf>

namespace ab::ui {

void saveImageAtomically(const QImage& image, const QString& path)
{
    if (QFileInfo(path).suffix().toLower() != "png")
        throw InputError(path.toStdString() + ": the 3D view is saved as PNG (use .png)");
    if (image.isNull())
        throw InputError(path.toStdString() + ": there is no image to save");
    checkWritable(path.toStdString());
    // Encoded in memory, then written through the one output path (core/io/atomic_file.h).
    QByteArray bytes;
    QBuffer file(&bytes);
    file.open(QIODevice::WriteOnly);
    if (!image.save(&file, "PNG"))
        throw InputError(path.toStdString() + ": PNG encoding failed");
    writeFileAtomically(path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())));
}

namespace {

// Passes characters through to `target`, counting lines; every `every` lines it tells
// `progress`, and throws ExportCancelled when told to stop (writeFileAtomically then
// removes its temporary file).
class LineCounter : public std::streambuf {
public:
    LineCounter(std::streambuf* target, std::size_t total, const ExportProgress& progress)
        : target_(target), total_(total), progress_(progress)
    {
    }

protected:
    int_type overflow(int_type c) override
    {
        if (traits_type::eq_int_type(c, traits_type::eof()))
            return traits_type::not_eof(c);
        if (traits_type::to_char_type(c) == '\n' && ++lines_ % every == 0 && !progress_(lines_, total_))
            throw ExportCancelled();
        return target_->sputc(traits_type::to_char_type(c));
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override
    {
        for (std::streamsize i = 0; i < n; ++i)
            if (s[i] == '\n' && ++lines_ % every == 0 && !progress_(lines_, total_))
                throw ExportCancelled();
        return target_->sputn(s, n);
    }
    int sync() override { return target_->pubsync(); }

private:
    static constexpr std::size_t every = 4096;
    std::streambuf* target_;
    std::size_t total_;
    const ExportProgress& progress_;
    std::size_t lines_ = 0;
};

} // namespace

void saveChartCsv(const ChartData& data, const QString& path, const ExportProgress& progress)
{
    const std::size_t rows = data.run->size() + data.comments.size() + 1; // the comments, the header, a row a sample
    writeFileAtomically(path.toStdString(), [&](std::ostream& out) {
        if (!progress) {
            writeChartCsv(out, data);
            return;
        }
        LineCounter counter(out.rdbuf(), rows, progress);
        std::ostream counted(&counter);
        counted.exceptions(std::ios::badbit);
        writeChartCsv(counted, data);
        counted.flush();
        if (!progress(rows, rows))
            throw ExportCancelled();
    });
}

} // namespace ab::ui
