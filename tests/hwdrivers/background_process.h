/* Test helper: a child process started with fork/exec (stdout+stderr to a
 * log file), stopped with SIGTERM (then SIGKILL) and reaped by the destructor. */
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

class CBackgroundProcess
{
   public:
	/** `stdinPath`: file or terminal opened as the child's standard input. */
	CBackgroundProcess(const std::vector<std::string>& argv, const std::string& logPath,
					   const std::string& stdinPath = "/dev/null")
		: m_log(logPath)
	{
		m_pid = fork();
		if (m_pid < 0) throw std::runtime_error("fork failed");
		if (m_pid == 0)
		{
			const int fd = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
			dup2(fd, 1);
			dup2(fd, 2);
			setsid();  // own session: a terminal given as stdin can become its controlling tty
			const int in = ::open(stdinPath.c_str(), O_RDWR);
			dup2(in, 0);
			std::vector<char*> args;
			for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
			args.push_back(nullptr);
			execv(args[0], args.data());
			_exit(127);
		}
	}
	~CBackgroundProcess() { stop(SIGTERM); }

	/** Waits until the log contains `text`; false on timeout or exit. */
	bool waitForLog(const std::string& text, double timeout_s) const
	{
		const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
		while (std::chrono::steady_clock::now() < end)
		{
			if (log().find(text) != std::string::npos) return true;
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
		}
		return false;
	}
	std::string log() const
	{
		std::ifstream f(m_log);
		std::stringstream ss;
		ss << f.rdbuf();
		return ss.str();
	}
	/** Sends `sig`, waits up to 5 s, then SIGKILL; returns the exit status (-1 if killed). */
	int stop(int sig)
	{
		if (m_pid <= 0) return m_status;
		kill(m_pid, sig);
		return wait(5.0);
	}
	/** Waits for the exit (SIGKILL after timeout_s). */
	int wait(double timeout_s)
	{
		if (m_pid <= 0) return m_status;
		const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
		int st = 0;
		while (waitpid(m_pid, &st, WNOHANG) == 0)
		{
			if (std::chrono::steady_clock::now() > end)
			{
				kill(m_pid, SIGKILL);
				waitpid(m_pid, &st, 0);
				break;
			}
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
		}
		m_pid = -1;
		m_status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
		return m_status;
	}
	pid_t pid() const { return m_pid; }

   private:
	pid_t m_pid = -1;
	int m_status = -1;
	std::string m_log;
};
