MODULE Robot
    ! Written for the test (issue 28): the robot task tells the communication task it runs
    ! by an output only it sets.
    PROC main()
        SetDO doRobBusy, 1;
        WHILE TRUE DO
            WaitDO doCommReady, 1;
            WaitTime 1;
        ENDWHILE
    ENDPROC
ENDMODULE
