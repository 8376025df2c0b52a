MODULE trap_during_waituntil
  ! Tests: interrupts are served while WaitUntil waits; a trap that makes the
  ! condition TRUE ends the wait.
  VAR intnum tmr;
  VAR bool ready := FALSE;
  PROC main()
    CONNECT tmr WITH onTime;
    ITimer \Single, 1, tmr;
    TPWrite "waiting";
    WaitUntil ready;
    TPWrite "ready";
  ENDPROC
  TRAP onTime
    TPWrite "trap sets ready";
    ready := TRUE;
  ENDTRAP
ENDMODULE
