MODULE booked_recovery
  ! Error numbers booked at run time and listed in ERROR handlers, in the style of
  ! ABB's StateMachine add-in (VAR errnum CHANGE_STATE := -1; BookErrNo;
  ! ERROR (CHANGE_STATE)).
  VAR errnum ERR_GRIP_LOST := -1;
  VAR errnum ERR_BELT_JAM := -1;
  PERS num nRecovered := 0;
  PERS num nAttempts := 0;
  PERS bool bWrongHandler := FALSE;

  PROC main()
    BookErrNo ERR_GRIP_LOST;
    BookErrNo ERR_BELT_JAM;
    Pick;
    Pick;
  ERROR (ERR_GRIP_LOST)
    Incr nRecovered;
    TRYNEXT;
  ENDPROC

  PROC Pick()
    Incr nAttempts;
    IF diGripOk = 0 RAISE ERR_GRIP_LOST;
  ERROR (ERR_BELT_JAM)
    ! a handler listing another booked number does not take ERR_GRIP_LOST
    bWrongHandler := TRUE;
    TRYNEXT;
  ENDPROC
ENDMODULE
