MODULE LibraryBackupGaps
    ! Issue 28: what backups use and rapidmc refused. The electronically linked motors
    ! option's routine Linked_m_exe (called by its system module LINKEDM.sys), the system
    ! data C_MOTSET, and an untyped aggregate in a cross product. Each wrong value reaches
    ! a division by zero, so no_runtime_error pins the values.
    VAR pos v := [1, 0, 0];
    VAR pos w;
    VAR num zero := 0;
    VAR num ratio := 0;

    PROC Linked_m()
        Linked_m_exe;
    ENDPROC

    PROC main()
        Linked_m;
        w := [0, 0, 1] * v;
        IF w.x <> 0 OR w.y <> 1 OR w.z <> 0 ratio := 1 / zero;
        IF C_MOTSET.vel.oride <> 100 ratio := 1 / zero;
    ENDPROC
ENDMODULE
