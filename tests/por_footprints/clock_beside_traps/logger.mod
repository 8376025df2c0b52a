MODULE Logger
  ! a logger timing its own work on its own clock, beside the server's traps
  PERS bool ready := FALSE;
  VAR clock watch;
  VAR num took := 0;
  VAR string line := "";
  PROC main()
    ClkReset watch;
    ClkStart watch;
    line := "t " + NumToStr(ClkRead(watch), 3);
    took := ClkRead(watch);
    ClkStop watch;
    SetDO doLamp, 1;
    ready := TRUE;
    line := line + " done";
  ENDPROC
ENDMODULE
