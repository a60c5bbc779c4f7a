//! The numbers the language shows for nodes (NOEUD n, NOEUD p). Objects
//! hold nodes by their index in the node table, which never changes; TASS
//! only changes the numbers, so renumbering leaves every mesh, field and
//! matrix valid.

/// A permutation of the nodes that existed at the last renumbering; nodes
/// created later keep their index as their number (they come after).
#[derive(Debug, Clone, Default)]
pub struct NodeNumbering {
    /// `order[k]`: the node numbered k (0-based).
    order: Vec<usize>,
    /// `rank[i]`: the number (0-based) of node i; the inverse of `order`.
    rank: Vec<usize>,
}

impl NodeNumbering {
    /// The 0-based number of node `id`.
    pub fn number(&self, id: usize) -> usize {
        self.rank.get(id).copied().unwrap_or(id)
    }

    /// The node whose 0-based number is `k`.
    pub fn node(&self, k: usize) -> usize {
        self.order.get(k).copied().unwrap_or(k)
    }

    /// Renumber the `count` nodes: `first` (distinct node indices) get
    /// the numbers 0..first.len() in that order, the others follow in
    /// their current order. Returns the nodes in their former number
    /// order (element i of TASS's result is the node formerly numbered i).
    pub fn renumber(&mut self, count: usize, first: &[usize]) -> Vec<usize> {
        let former: Vec<usize> = (0..count).map(|k| self.node(k)).collect();
        let mut taken = vec![false; count];
        let mut order = Vec::with_capacity(count);
        for &n in first {
            if n < count && !taken[n] {
                taken[n] = true;
                order.push(n);
            }
        }
        order.extend(former.iter().copied().filter(|&n| !taken[n]));
        let mut rank = vec![0; count];
        for (k, &n) in order.iter().enumerate() {
            rank[n] = k;
        }
        self.order = order;
        self.rank = rank;
        former
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn given_nodes_come_first_and_the_rest_keep_their_order() {
        let mut n = NodeNumbering::default();
        let former = n.renumber(5, &[3, 1]);
        assert_eq!(former, vec![0, 1, 2, 3, 4]);
        assert_eq!((0..5).map(|k| n.node(k)).collect::<Vec<_>>(), vec![3, 1, 0, 2, 4]);
        assert_eq!(n.number(3), 0);
        assert_eq!(n.number(7), 7);
        let former = n.renumber(6, &[0]);
        assert_eq!(former, vec![3, 1, 0, 2, 4, 5]);
        assert_eq!(n.node(1), 3);
    }
}
