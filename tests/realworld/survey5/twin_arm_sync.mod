MODULE TwinArmSync
    ! The left arm's task of a two-arm cell: both arms meet at sync points before a
    ! joint move. The task list and the sync identifiers are declared in the cell's
    ! shared module, which is not given. Written for rapidmc's survey round 5.
    PERS num parts_done := 0;

    PROC main()
        WaitSyncTask sync_start, arm_tasks \TimeOut:=30;
        WHILE parts_done < 3 DO
            MoveJ hand_over, v500, z10, tool0;
            WaitSyncTask sync_handover, arm_tasks;
            parts_done := parts_done + 1;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_WAITSYNCTASK THEN
            TPWrite "the right arm did not come";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
