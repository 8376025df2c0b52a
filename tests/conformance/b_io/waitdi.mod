MODULE MainModule
  ! Tests: WaitDI continues at once when the input already has the awaited value (di1=1 by
  ! --io; di2 is 0).
  VAR signaldi diStart;
  VAR signaldi diStop;
  PROC main()
    AliasIO "di1", diStart;
    AliasIO "di2", diStop;
    WaitDI diStart, 1;
    TPWrite "start seen";
    WaitDI diStop, 0;
    TPWrite "stop low";
  ENDPROC
ENDMODULE
