MODULE Monitor
    ! Written for the test (issue 28): the head task serves the same command word. Neither
    ! task writes anything but 0 to it, so only the upper system ends the wait: checked
    ! alone, the wait is no deadlock although the other task writes nCmd with a constant.
    PERS num nCmd := 0;

    PROC main()
        nCmd := 0;
        WHILE TRUE DO
            WaitUntil nCmd <> 0;
            TEST nCmd
            CASE 1:
                TPWrite "move";
            DEFAULT:
                TPWrite "other";
            ENDTEST
            WaitUntil nCmd = 0;
        ENDWHILE
    ENDPROC
ENDMODULE
