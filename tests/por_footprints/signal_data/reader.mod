MODULE Reader
  ! Signal data bound at run time (AliasIO) may stand for any signal: a read of it
  ! conflicts with every task that sets some signal, and a task reading it names every
  ! signal (its own writes of a signal no other task names stay its own).
  VAR signaldi diBound;
  VAR num seen := 0;
  PROC main()
    AliasIO "diPart", diBound;
    IF diBound = 1 THEN                  ! SHARED
      seen := 1;                         ! LOCAL
    ENDIF
    Set doMine;                          ! LOCAL
  ENDPROC
ENDMODULE
