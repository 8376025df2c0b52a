MODULE Conveyor
  ! Issue 28: a name the program assigns and also compares with 0 or 1 is data of a module
  ! not given (a handshake flag), not a configured digital input: signals are not assigned
  ! with := nor written by instructions (Incr, TPReadNum, GetDataVal). The stubs declare
  ! partReady, nBoxCount, nCycle, nAnswer and ao_Level (named like an analog output, but
  ! GetDataVal writes it); diBoxAtEnd, compared with 1 and never written, stays a
  ! configured input and is not declared.
  PROC main()
    partReady := 0;
    WHILE partReady = 0 DO
      IF diBoxAtEnd = 1 THEN
        partReady := 1;
      ENDIF
    ENDWHILE
    IF nBoxCount = 1 THEN
      TPWrite "first box";
    ENDIF
    nBoxCount := nBoxCount + 1;
    Incr nCycle;
    IF nCycle = 1 TPWrite "first cycle";
    TPReadNum nAnswer, "Go on? (1 = yes)";
    IF nAnswer = 0 Stop;
    GetDataVal "nLevel", ao_Level;
    IF ao_Level > 2.5 TPWrite "high";
  ENDPROC
ENDMODULE
