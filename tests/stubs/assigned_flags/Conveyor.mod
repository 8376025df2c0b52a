MODULE Conveyor
  ! Issue 28: a name the program assigns and also compares with 0 or 1 is data of a module
  ! not given (a handshake flag), not a configured digital input: signals are not assigned
  ! with :=. The stubs declare partReady and nBoxCount; diBoxAtEnd, compared with 1 and
  ! never assigned, stays a configured input and is not declared.
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
  ENDPROC
ENDMODULE
