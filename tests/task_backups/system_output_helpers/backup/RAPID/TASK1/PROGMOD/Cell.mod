MODULE Cell
    ! Written for the test (issue 28): the task waits through helper routines that take the
    ! output as a parameter.  WaitHigh and WaitLow only read it (WaitDO), SetHigh sets it
    ! (through Out, SetDO).  doMotorsOn is set by the controller alone, doCycle by a
    ! cross-connection and by this task's own SetHigh.
    VAR num rounds := 0;

    PROC main()
        WaitHigh doMotorsOn;
        rounds := rounds + 1;
        SetHigh doCycle;
        WaitHigh doCycle;
        WaitLow doCycle;
    ENDPROC

    PROC WaitHigh(VAR signaldo s)
        WaitDO s, 1;
    ENDPROC

    PROC WaitLow(VAR signaldo s)
        Check s;
    ENDPROC

    PROC Check(VAR signaldo s)
        WaitDO s, 0;
    ENDPROC

    PROC SetHigh(VAR signaldo s)
        Out s;
    ENDPROC

    PROC Out(VAR signaldo s)
        SetDO s, 1;
    ENDPROC
ENDMODULE
