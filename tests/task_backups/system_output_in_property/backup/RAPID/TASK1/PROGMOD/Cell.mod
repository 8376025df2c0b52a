MODULE Cell
    ! Written for the test (issue 28): the task waits until the controller's system output
    ! says the motors are on, then divides by a count that stays 0 when they are off.
    VAR num rounds := 0;
    VAR num share := 0;

    PROC main()
        WaitDO doMotorsOn, 1;
        SetDO doCycle, 1;
        IF DOutput(doMotorsOn) = 1 rounds := rounds + 1;
        share := 10 / rounds;
        WaitDO doCycle, 0;
    ENDPROC
ENDMODULE
