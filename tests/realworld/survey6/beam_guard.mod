MODULE beam_guard
  ! Signal parameters handed on, in the style of the survey's utility libraries
  ! (a TimeWaitDI that passes its VAR signaldi to a helper function, which waits
  ! on it with a time limit) and of gripper routines reading their output.
  PERS num nPulses := 0;
  PERS bool bBeamSteady := FALSE;

  PROC main()
    TimeWaitDI diLaser, 5;
    bBeamSteady := TRUE;
    PulseTwice doClamp;
  ENDPROC

  PROC TimeWaitDI(VAR signaldi inputDI, num timeToWait)
    WHILE NOT SteadyFor(inputDI, timeToWait) DO
      WaitTime 0.1;
    ENDWHILE
  ENDPROC

  LOCAL FUNC bool SteadyFor(VAR signaldi inputDI, num timeToWait)
    VAR bool answer := FALSE;
    IF inputDI = 1 THEN
      WaitDI inputDI, 0 \MaxTime:=timeToWait;
    ENDIF
    RETURN answer;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      answer := TRUE;
      TRYNEXT;
    ENDIF
  ENDFUNC

  PROC PulseTwice(VAR signaldo sig)
    Pulse sig;
    Pulse sig;
  ENDPROC

  PROC Pulse(VAR signaldo sig)
    SetDO sig, 1;
    IF DOutput(sig) = 1 Incr nPulses;
    SetDO sig, 0;
  ENDPROC
ENDMODULE
