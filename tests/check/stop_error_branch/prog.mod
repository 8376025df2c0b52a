MODULE StopErrorBranch
    ! A cell cycle with a fault branch: TPWrite, Stop, then recovery.  The
    ! recovery resets the counter wrongly (to 5), which only a restart reaches.
    VAR num cycle := 0;
    PROC main()
        WHILE TRUE DO
            cycle := cycle + 1;
            IF DInput(diFault) = 1 THEN
                TPWrite "Gripper fault";
                Stop;
                cycle := 5;
            ENDIF
            IF cycle > 3 cycle := 0;
        ENDWHILE
    ENDPROC
ENDMODULE
