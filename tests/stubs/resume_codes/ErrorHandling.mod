MODULE ErrorHandling
  ! Issue 19: a TEST whose subject and CASE values are all names of a module not given (an
  ! add-in's resume codes): nothing else types them, so num is assumed and the values are
  ! told apart (1, 2, 3). A component of a missing record given only to ErrWrite, whose
  ! arguments are anytype, gets no anytype component (num assumed, said in a comment). An
  ! interrupt number of a module not given is declared VAR: ISignalDO takes a variable.
  PROC main()
    TEST nResumeType
    CASE RESUME_KILL:
      TPWrite "kill";
    CASE RESUME_SKIP_SEAM:
      TPWrite "skip seam";
    CASE RESUME_SKIP_PART:
      TPWrite "skip part";
    ENDTEST
    ErrWrite "weld", "track" \RL2:=ValToStr(seamTrack.gain_y);
    ISignalDO doArcOn, 0, intArcOn;
  ENDPROC
ENDMODULE
