MODULE Server
  ! a server whose interrupts stay connected: a timer and an output the logger sets
  PERS bool ready := FALSE;
  VAR intnum irTick;
  VAR intnum irLamp;
  VAR num hits := 0;
  VAR num n := 0;
  PROC main()
    CONNECT irTick WITH onTick;
    ITimer \Single, 1, irTick;
    CONNECT irLamp WITH onLamp;
    ISignalDO doLamp, 1, irLamp;
    FOR i FROM 1 TO 2 DO
      n := (n + 1) MOD 2;
      IF ready n := 0;
    ENDFOR
  ENDPROC
  TRAP onTick
    hits := (hits + 1) MOD 2;
  ENDTRAP
  TRAP onLamp
    ready := FALSE;
  ENDTRAP
ENDMODULE
