MODULE Robot
    ! Written for the test (issue 28): the robot task serves commands an upper system (a
    ! PLC or a PC) writes into a shared PERS; the task itself only clears it to 0.
    PERS num nCmd := 0;

    PROC main()
        nCmd := 0;
        WHILE TRUE DO
            WaitUntil nCmd <> 0;
            TPWrite "robot: command";
            WaitUntil nCmd = 0;
        ENDWHILE
    ENDPROC
ENDMODULE
