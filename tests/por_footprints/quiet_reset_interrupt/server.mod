MODULE Server
  ! a command server whose reset interrupt watches an output only its own TRAP sets
  ! (joseballester's USER_RESET_MOTION): not pending, it leaves the server ample
  PERS bool mutex := FALSE;
  PERS num toolX := 0;
  VAR intnum irReset;
  VAR num code := 0;
  VAR num served := 0;
  VAR string reply := "";
  PROC main()
    CONNECT irReset WITH onReset;
    ISignalDO doReset, 1, irReset;
    FOR i FROM 1 TO 2 DO
      code := (code + 1) MOD 3;  ! LOCAL
      TEST code
      CASE 1:
        WHILE mutex DO  ! SHARED
        ENDWHILE
        mutex := TRUE;  ! SHARED
        toolX := code;
        mutex := FALSE;
      DEFAULT:
        served := served + 1;
      ENDTEST
      reply := "ok " + NumToStr(code, 0);  ! LOCAL
    ENDFOR
  ENDPROC
  TRAP onReset
    SetDO doReset, 0;
    served := 0;
  ENDTRAP
ENDMODULE
