MODULE itimer_cyclic
  ! Tests: a cyclic ITimer 1 fires every second (at 1, 2 and 3 s during a
  ! 3.5 s wait); after IDelete it fires no more.
  VAR intnum tmr;
  VAR num ticks := 0;
  PROC main()
    CONNECT tmr WITH onTick;
    ITimer 1, tmr;
    WaitTime 3.5;
    IDelete tmr;
    TPWrite "ticks=" \Num:=ticks;
    WaitTime 3;
    TPWrite "ticks=" \Num:=ticks;
  ENDPROC
  TRAP onTick
    ticks := ticks + 1;
  ENDTRAP
ENDMODULE
