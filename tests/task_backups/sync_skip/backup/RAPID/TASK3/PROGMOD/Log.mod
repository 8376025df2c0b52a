MODULE Log
  VAR num ticks := 0;
  PROC main()
    ! a background task that never ends: the others' deadlock is not the whole program's
    WHILE TRUE DO
      ticks := (ticks + 1) MOD 2;
    ENDWHILE
  ENDPROC
ENDMODULE
