MODULE itimer_single
  ! Tests: ITimer \Single, 0.5 fires once, 0.5 s after ordering; the trap
  ! runs during WaitTime, which then completes.
  VAR intnum tmr;
  VAR num count := 0;
  PROC main()
    CONNECT tmr WITH onTime;
    ITimer \Single, 0.5, tmr;
    WaitTime 2;
    TPWrite "count=" \Num:=count;
  ENDPROC
  TRAP onTime
    count := count + 1;
    TPWrite "timer";
  ENDTRAP
ENDMODULE
