MODULE Cell
    ! Written for the test (issue 28): the task sets the system output doMotorsOn itself,
    ! through an optional parameter passed on as \Sig?Sig to the routine that sets it.
    VAR num share := 0;

    PROC main()
        Outer \Sig:=doMotorsOn;
        IF DOutput(doMotorsOn) = 0 share := 1 / 0;
    ENDPROC

    PROC Outer(\VAR signaldo Sig)
        Pulse \Sig?Sig;
    ENDPROC

    PROC Pulse(\VAR signaldo Sig)
        IF Present(Sig) SetDO Sig, 1;
    ENDPROC
ENDMODULE
